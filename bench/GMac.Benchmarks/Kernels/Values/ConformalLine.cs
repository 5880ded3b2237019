namespace GMac.Benchmarks.Kernels.Values;

/// <summary>The coefficients of the conformal line p ∧ q ∧ ni: its direction on no∧eᵢ∧ni and its moment on eᵢ∧eⱼ∧ni.</summary>
public struct ConformalLine
{
    public Vec3 Direction;
    public double E12Ni;
    public double E13Ni;
    public double E23Ni;
}
