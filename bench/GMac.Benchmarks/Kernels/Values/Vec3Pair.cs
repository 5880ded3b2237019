namespace GMac.Benchmarks.Kernels.Values;

/// <summary>Two 3D vectors.</summary>
public struct Vec3Pair
{
    public Vec3 U;
    public Vec3 V;
}
