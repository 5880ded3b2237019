namespace GMac.Benchmarks.Kernels.Values;

/// <summary>A dual sphere no·No + c_E + Ni·ni of the conformal model, by coefficient.</summary>
public struct DualSphere
{
    public double No;
    public double E1;
    public double E2;
    public double E3;
    public double Ni;
}
