namespace GMac.Dsl.Semantics;

public enum UnaryOperator
{
    Negate,
    Reverse,
    GradeInvolution,
    CliffordConjugate,
    Inverse,
    Dual,
    Undual,
    Exp,
    Norm,
    Norm2,
    QuasiNorm,
    QuasiNorm2,
}
