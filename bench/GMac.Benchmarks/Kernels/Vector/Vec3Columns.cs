namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>A 3D vector per item, in columns: item i is (x[i], y[i], z[i]); the members are named as the class bindings read them.</summary>
public readonly struct Vec3Columns
{
    public readonly double[] x, y, z;

    /// <summary>Columns k… of <paramref name="c"/>.</summary>
    public Vec3Columns(double[][] c, int k) => (x, y, z) = (c[k], c[k + 1], c[k + 2]);
}
