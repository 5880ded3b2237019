using Twister;

namespace RayTracer.Tests.Geometry.Parametric;

/// <summary>Closed-form shapes for the Twister objects, oriented like the ray tracer's own primitives.</summary>
internal static class ClosedForms
{
    /// <summary>Unit-speed-free sphere about the origin; u around the y axis, v from the south pole to the north.</summary>
    public sealed class Sphere(double radius) : IParametricSurface
    {
        public TwistablePoint PointAt(double u, double v)
        {
            double a = 2 * Math.PI * u, b = Math.PI * v;
            return new(radius * Math.Sin(b) * Math.Sin(a), -radius * Math.Cos(b), radius * Math.Sin(b) * Math.Cos(a));
        }

        /// <summary>∂S/∂u × ∂S/∂v: outward, length 2π²r² sin(πv).</summary>
        public TwistableVector NormalAt(double u, double v)
        {
            var p = PointAt(u, v);
            var k = 2 * Math.PI * Math.PI * radius * Math.Sin(Math.PI * v);
            return new(k * p.x, k * p.y, k * p.z);
        }
    }

    /// <summary>Torus about the y axis: u around the axis, v around the tube.</summary>
    public sealed class Torus(double swept, double tube) : IParametricSurface
    {
        public TwistablePoint PointAt(double u, double v)
        {
            double a = 2 * Math.PI * u, b = 2 * Math.PI * v, ring = swept + tube * Math.Cos(b);
            return new(ring * Math.Sin(a), tube * Math.Sin(b), ring * Math.Cos(a));
        }

        /// <summary>∂S/∂u × ∂S/∂v: outward, length 4π² r (R + r cos 2πv).</summary>
        public TwistableVector NormalAt(double u, double v)
        {
            double a = 2 * Math.PI * u, b = 2 * Math.PI * v;
            var k = 4 * Math.PI * Math.PI * tube * (swept + tube * Math.Cos(b));
            return new(k * Math.Cos(b) * Math.Sin(a), k * Math.Sin(b), k * Math.Cos(b) * Math.Cos(a));
        }
    }

    /// <summary>Circle of the given radius in the plane z = 0 about the origin.</summary>
    public sealed class Circle(double radius) : IParametricCurve
    {
        public TwistablePoint PointAt(double t) => new(radius * Math.Cos(2 * Math.PI * t), radius * Math.Sin(2 * Math.PI * t), 0);

        public TwistableVector TangentAt(double t) =>
            new(-2 * Math.PI * radius * Math.Sin(2 * Math.PI * t), 2 * Math.PI * radius * Math.Cos(2 * Math.PI * t), 0);
    }

    /// <summary>Helix about the z axis: <paramref name="turns"/> turns rising by <paramref name="height"/>.</summary>
    public sealed class Helix(double radius, double height, double turns) : IParametricCurve
    {
        public TwistablePoint PointAt(double t) =>
            new(radius * Math.Cos(2 * Math.PI * turns * t), radius * Math.Sin(2 * Math.PI * turns * t), height * t);

        public TwistableVector TangentAt(double t)
        {
            var w = 2 * Math.PI * turns;
            return new(-w * radius * Math.Sin(w * t), w * radius * Math.Cos(w * t), height);
        }
    }
}
