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
    Norm,
    Norm2,
    QuasiNorm,
    QuasiNorm2,
}
