namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>A rotor per item (w scalar, x y z bivector, as Rotor3), in columns: item i is (w[i], x[i], y[i], z[i]); the members are named as the class bindings read them.</summary>
public readonly struct Rotor3Columns
{
    public readonly double[] w, x, y, z;

    /// <summary>Columns k… of <paramref name="c"/>.</summary>
    public Rotor3Columns(double[][] c, int k) => (w, x, y, z) = (c[k], c[k + 1], c[k + 2], c[k + 3]);
}
