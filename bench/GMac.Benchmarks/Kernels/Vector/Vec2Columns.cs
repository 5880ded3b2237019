namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>A 2D vector per item, in columns: item i is (x[i], y[i]); the members are named as the class bindings read them.</summary>
public readonly struct Vec2Columns
{
    public readonly double[] x, y;

    /// <summary>Columns k… of <paramref name="c"/>.</summary>
    public Vec2Columns(double[][] c, int k) => (x, y) = (c[k], c[k + 1]);
}
