namespace GMac.Benchmarks.Kernels.Values;

/// <summary>The line parameters of the closest points of two lines.</summary>
public struct LineParameters
{
    public double T1;
    public double T2;
}
