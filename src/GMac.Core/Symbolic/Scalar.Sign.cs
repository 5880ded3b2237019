namespace GMac.Core.Symbolic;

public sealed partial class Scalar
{
    /// <summary>
    /// The sign this scalar has for every real value of its atoms, or null when its structure does
    /// not tell: −1 means ≤ 0 and +1 means ≥ 0 (zero is allowed at some points). Decided from a
    /// constant, from terms that are all even powers with coefficients of one sign (a sum of
    /// squares), or from an exact polynomial square root (c·r², c a constant).
    /// </summary>
    public int? KnownSign()
    {
        if (TryGetConstant(out var c)) return c.Sign;
        var sign = _terms[0].Coefficient.Sign;
        if (_terms.All(t => t.Coefficient.Sign == sign && t.Monomial.Factors.All(f => f.Power % 2 == 0))) return sign;
        var scaled = sign < 0 ? -this : this;
        return scaled.TrySquareRoot(out _) ? sign : null;
    }

    /// <summary>A polynomial r with r² = this (either sign of r), when the structure shows one.</summary>
    public bool TrySquareRoot(out Scalar root)
    {
        if (_terms.Length == 1 && PolynomialSquareRoot.HalfOf(_terms[0]) is { } half)
        {
            root = FromTerm(half.Coefficient, half.Monomial);
            return true;
        }
        return PolynomialSquareRoot.TryRoot(this, out root);
    }

    /// <summary>Whether a term divides by an atom or by a sum: such a scalar may be 0/0 where its divisor vanishes.</summary>
    public bool HasDivision() =>
        _terms.Any(t => t.Monomial.Factors.Any(f => f.Power < 0 || f.Atom.Kind == AtomKind.Inverse));
}
