namespace GMac.Benchmarks.Kernels.Values;

/// <summary>Two 2D vectors: a Julia point and its constant.</summary>
public struct Vec2Pair
{
    public Vec2 X;
    public Vec2 C;
}
