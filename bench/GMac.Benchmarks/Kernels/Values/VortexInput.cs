namespace GMac.Benchmarks.Kernels.Values;

/// <summary>The arguments of the vortexS field of thesis Table 7-1.</summary>
public struct VortexInput
{
    public Vec3 P;
    public Vec3 A;
    public double Omega;
    public double Gamma;
}
