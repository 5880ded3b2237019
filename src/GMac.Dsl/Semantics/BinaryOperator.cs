namespace GMac.Dsl.Semantics;

public enum BinaryOperator
{
    Add,
    Subtract,
    /// <summary>Product with a scalar (<c>*</c>, <c>scale</c>).</summary>
    Multiply,
    /// <summary>Division by a scalar (<c>/</c>, <c>div_by_scalar</c>).</summary>
    Divide,
    Power,
    Gp,
    Op,
    Sp,
    Lcp,
    Rcp,
    Fdp,
    Hip,
    Cp,
    Acp,
    /// <summary>The regressive product <c>vee</c>: ★⁻¹(★A ∧ ★B), metric independent.</summary>
    Vee,
}
