namespace GMac.Benchmarks.Kernels.Values;

/// <summary>A 3D rotor R = w + x e2e3 + y e3e1 + z e1e2, named as in thesis (7.7).</summary>
public struct Rotor3
{
    public double w;
    public double x;
    public double y;
    public double z;

    public Rotor3(double w, double x, double y, double z) => (this.w, this.x, this.y, this.z) = (w, x, y, z);
}
