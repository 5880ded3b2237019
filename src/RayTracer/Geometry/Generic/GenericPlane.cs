using RayTracer.Bounds;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Generic;

/// <summary>The plane y = 0 with normal +y. Place it with an <see cref="Instance"/>.</summary>
public class GenericPlane : GeometricObject
{
    public override bool Intersect(in Ray ray, out double t)
    {
        t = ray.d.y == 0 ? 0 : -ray.o.y / ray.d.y;
        if (ray.d.y == 0 || !(t > ray.tMin) || !double.IsFinite(t))
        {
            return false;
        }

        return Accept(ray.o.x + t * ray.d.x, ray.o.z + t * ray.d.z);
    }

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!Intersect(ray, out tmin))
        {
            return false;
        }

        var p = ray.At(tmin);
        sr.Normal = new Normal3D(0, 1, 0);
        sr.LocalHitPoint = p;
        sr.TextureCoordinates = Coordinates(p.x, p.z);
        sr.Material = Material;
        return true;
    }

    public override BoundingBox GetBoundingBox() => BoundingBox.Infinite;

    /// <summary>Which points (x, 0, z) of the plane belong to the object; the plane keeps all of them.</summary>
    protected virtual bool Accept(double x, double z) => true;

    protected virtual TextureCoordinates Coordinates(double x, double z) => new(x, z);
}
