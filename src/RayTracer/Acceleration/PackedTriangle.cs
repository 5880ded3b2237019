using RayTracer.Maths;

namespace RayTracer.Acceleration;

/// <summary>A triangle as the ray test wants it (v0 and two edges), stored inline for cache-friendly leaves.</summary>
internal struct PackedTriangle
{
    public Point3D V0;
    public Vector3D E1;
    public Vector3D E2;

    public static PackedTriangle From(Point3D v0, Point3D v1, Point3D v2) => new() { V0 = v0, E1 = v1 - v0, E2 = v2 - v0 };
}
