namespace GMac.Benchmarks.Kernels.Values;

/// <summary>Two unit rotors and an interpolation parameter in [0, 1].</summary>
public struct RotorPair
{
    public Rotor3 R1;
    public Rotor3 R2;
    public double Alpha;
}
