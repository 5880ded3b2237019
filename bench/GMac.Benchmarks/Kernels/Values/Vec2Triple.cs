namespace GMac.Benchmarks.Kernels.Values;

/// <summary>Three 2D vectors: a projected triangle.</summary>
public struct Vec2Triple
{
    public Vec2 A;
    public Vec2 B;
    public Vec2 C;
}
