using RayTracer.Maths;

namespace RayTracer.Tracing;

/// <summary>A ray o + t d. The direction is not required to be unit length.</summary>
public struct Ray
{
    public Point3D o;
    public Vector3D d;

    public Ray(Point3D origin, Vector3D direction)
    {
        o = origin;
        d = direction;
    }

    public readonly Point3D At(double t) => new(o.x + t * d.x, o.y + t * d.y, o.z + t * d.z);

    public override readonly string ToString() => $"{o} + t{d}";
}
