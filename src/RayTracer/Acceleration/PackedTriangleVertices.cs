using RayTracer.Maths;

namespace RayTracer.Acceleration;

/// <summary>A triangle as the Plücker test wants it: its three vertices, from which it builds the edge lines.</summary>
internal struct PackedTriangleVertices
{
    public Point3D V0;
    public Point3D V1;
    public Point3D V2;
}
