namespace GMac.Benchmarks.Kernels.Values;

/// <summary>Four 3D points.</summary>
public struct Vec3Quad
{
    public Vec3 P1;
    public Vec3 P2;
    public Vec3 P3;
    public Vec3 P4;
}
