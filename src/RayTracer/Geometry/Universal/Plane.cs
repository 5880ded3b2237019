using RayTracer.Bounds;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Universal;

/// <summary>Infinite plane through a point with a given normal.</summary>
public sealed class Plane : GeometricObject
{
    public Plane(Point3D point, Normal3D normal)
    {
        if (normal.LengthSquared == 0)
        {
            throw new ArgumentException("A plane needs a non-zero normal.", nameof(normal));
        }

        Point = point;
        Normal = normal.Normalized();
    }

    public Point3D Point { get; }

    public Normal3D Normal { get; }

    public override bool Intersect(in Ray ray, out double t)
    {
        double denom = Normal.Dot(ray.d);
        t = denom == 0 ? 0 : Normal.Dot(Point - ray.o) / denom;
        return denom != 0 && t > ray.tMin && double.IsFinite(t);
    }

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!Intersect(ray, out tmin))
        {
            return false;
        }

        var p = ray.At(tmin);
        sr.Normal = Normal;
        sr.LocalHitPoint = p;
        sr.TextureCoordinates = default;
        sr.Material = Material;
        return true;
    }

    public override BoundingBox GetBoundingBox() => BoundingBox.Infinite;
}
