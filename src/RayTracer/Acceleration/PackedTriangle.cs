using RayTracer.Maths;

namespace RayTracer.Acceleration;

/// <summary>A triangle as the ray test wants it (v0 and two edges), stored inline for cache-friendly leaves.</summary>
internal struct PackedTriangle
{
    public Point3D V0;
    public Vector3D E1;
    public Vector3D E2;
}
