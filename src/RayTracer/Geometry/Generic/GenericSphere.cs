using RayTracer.Bounds;
using RayTracer.Geometry.Solvers;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Generic;

/// <summary>Sphere about the origin; shares its solver with the universal sphere. Place it with an <see cref="Instance"/>.</summary>
public sealed class GenericSphere : GeometricObject
{
    public GenericSphere(double radius = 1)
    {
        if (!(radius > 0))
        {
            throw new ArgumentOutOfRangeException(nameof(radius), radius, "A sphere needs a positive radius.");
        }

        Radius = radius;
    }

    public double Radius { get; }

    public override bool Intersect(in Ray ray, out double t) => SphereSolver.Nearest(ray, Point3D.Origin, Radius, out t);

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!SphereSolver.Nearest(ray, Point3D.Origin, Radius, out tmin))
        {
            return false;
        }

        var p = ray.At(tmin);
        var n = new Normal3D(p.x, p.y, p.z).Normalized();
        sr.Normal = n;
        sr.LocalHitPoint = p;
        sr.TextureCoordinates = Universal.Sphere.SphericalCoordinates(n);
        sr.Material = Material;
        return true;
    }

    public override BoundingBox GetBoundingBox() => new(new Point3D(-Radius), new Point3D(Radius));
}
