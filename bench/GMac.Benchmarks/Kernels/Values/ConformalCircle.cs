namespace GMac.Benchmarks.Kernels.Values;

/// <summary>The ten coefficients of the conformal circle p ∧ q ∧ r, named after their blades.</summary>
public struct ConformalCircle
{
    public double NoE12, NoE13, NoE23, E123, NoE1Ni, NoE2Ni, NoE3Ni, E12Ni, E13Ni, E23Ni;
}
