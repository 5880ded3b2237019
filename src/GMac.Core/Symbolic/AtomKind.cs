namespace GMac.Core.Symbolic;

/// <summary>
/// What an <see cref="Atom"/> stands for. The declaration order is the canonical order of
/// atoms inside a monomial, so variables print before constants and functions.
/// </summary>
public enum AtomKind
{
    Variable,
    Pi,
    Sin,
    Cos,
    Tan,
    Sqrt,
    Exp,
    Log,
    Atan2,
    Abs,
    /// <summary>pow(base, exponent) with an exponent that is not a constant integer.</summary>
    Pow,
    /// <summary>1/s for a sum s of two or more terms, normalized so its leading coefficient is 1.</summary>
    Inverse,
    // sinh and cosh as calls (Scalar.HyperbolicSine), where code needs sinh x accurate near 0 and e^x − e^−x cancels.
    Sinh,
    Cosh,
}
