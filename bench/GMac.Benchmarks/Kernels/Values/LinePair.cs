namespace GMac.Benchmarks.Kernels.Values;

/// <summary>Two lines P + t D.</summary>
public struct LinePair
{
    public Vec3 P1;
    public Vec3 D1;
    public Vec3 P2;
    public Vec3 D2;
}
