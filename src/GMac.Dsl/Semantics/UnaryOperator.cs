namespace GMac.Dsl.Semantics;

public enum UnaryOperator
{
    Negate,
    Reverse,
    GradeInvolution,
    CliffordConjugate,
    Inverse,
    /// <summary>adj(A)/⟨A adj(A)⟩₀: the inverse of any invertible multivector of a frame of at most 5 dimensions.</summary>
    GeneralInverse,
    Dual,
    Undual,
    /// <summary>Right complement: A ∧ rcomplement(A) = I on basis blades, metric independent.</summary>
    RightComplement,
    /// <summary>Left complement: lcomplement(A) ∧ A = I on basis blades, the inverse of the right one.</summary>
    LeftComplement,
    Exp,
    /// <summary>log of a rotor or motor: the bivector B with exp(B) = M, angles in [0, π).</summary>
    Log,
    /// <summary>Square root of a rotor or motor: N (N Ñ)^(−1/2) with N = 1 + R.</summary>
    VersorSqrt,
    Norm,
    Norm2,
    QuasiNorm,
    QuasiNorm2,
}
