using RayTracer.Bounds;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Generic;

/// <summary>Flat ring Inner ≤ √(x² + z²) ≤ Outer in the plane y = 0, normal +y.</summary>
public sealed class Annulus : GeometricObject
{
    public Annulus(double inner, double outer)
    {
        if (!(inner >= 0) || !(outer > inner))
        {
            throw new ArgumentException("An annulus needs 0 ≤ inner < outer.");
        }

        Inner = inner;
        Outer = outer;
    }

    public double Inner { get; }

    public double Outer { get; }

    public override bool Intersect(in Ray ray, out double t)
    {
        t = ray.d.y == 0 ? 0 : -ray.o.y / ray.d.y;
        if (ray.d.y == 0 || !(t > ray.tMin) || !double.IsFinite(t))
        {
            return false;
        }

        double x = ray.o.x + t * ray.d.x, z = ray.o.z + t * ray.d.z;
        double r2 = x * x + z * z;
        return r2 >= Inner * Inner && r2 <= Outer * Outer;
    }

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!Intersect(ray, out tmin))
        {
            return false;
        }

        var p = ray.At(tmin);
        double r = Math.Sqrt(p.x * p.x + p.z * p.z);
        sr.Normal = new Normal3D(0, 1, 0);
        sr.LocalHitPoint = p;
        sr.TextureCoordinates = new TextureCoordinates(
            Azimuth.Of(p.x, p.z) * MathConstants.InvTwoPi, (r - Inner) / (Outer - Inner));
        sr.Material = Material;
        return true;
    }

    public override BoundingBox GetBoundingBox() => new(-Outer, Outer, -Tolerances.BoundsPadding, Tolerances.BoundsPadding, -Outer, Outer);
}
