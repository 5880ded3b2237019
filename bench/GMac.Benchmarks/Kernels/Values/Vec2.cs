namespace GMac.Benchmarks.Kernels.Values;

/// <summary>A 2D vector; lower-case fields so that DSL class bindings (members x, y) read it.</summary>
public struct Vec2
{
    public double x;
    public double y;

    public Vec2(double x, double y) => (this.x, this.y) = (x, y);
}
