using GMac.Core.Numerics;

namespace GMac.Core.Symbolic;

/// <summary>
/// The exact square root r of a polynomial p = r², every atom treated as a variable. A norm of a
/// single coefficient, √(s·s), then reads |s| instead of the root of an expanded square.
/// </summary>
internal static class PolynomialSquareRoot
{
    // Beyond this the candidate's square costs more than the rule is worth.
    private const int MaxTerms = 256;

    /// <summary>
    /// The terms of p whose coefficient is a positive rational square and whose powers are all even
    /// are the candidate root's squares; the cross term with the first of them fixes each sign.
    /// The candidate is squared and compared, so a false answer only means no root was found.
    /// </summary>
    public static bool TryRoot(Scalar p, out Scalar root)
    {
        root = Scalar.Zero;
        var terms = p.TermArray;
        if (terms.Length < 3 || terms.Length > MaxTerms) return false;
        var halves = new List<Term>();
        foreach (var term in terms)
            if (HalfOf(term) is { } half) halves.Add(half);
        var k = halves.Count;
        if (k < 2 || (long)k * (k + 1) / 2 < terms.Length) return false;

        var byMonomial = new Dictionary<Monomial, Rational>(terms.Length);
        foreach (var term in terms) byMonomial[term.Monomial] = term.Coefficient;
        var first = Scalar.FromTerm(halves[0].Coefficient, halves[0].Monomial);
        var rootTerms = new List<Term>(k) { halves[0] };
        for (var i = 1; i < k; i++)
        {
            var cross = (first * Scalar.FromTerm(Rational.One, halves[i].Monomial)).TermArray[0].Monomial;
            if (!byMonomial.TryGetValue(cross, out var coefficient) || coefficient.IsZero) return false;
            rootTerms.Add(coefficient.Sign < 0 ? halves[i] with { Coefficient = -halves[i].Coefficient } : halves[i]);
        }
        var candidate = Scalar.FromTerms(rootTerms);
        if (candidate * candidate != p) return false;
        root = candidate;
        return true;
    }

    private static Term? HalfOf(Term term)
    {
        if (term.Coefficient.Sign <= 0 || !term.Coefficient.TryExactSqrt(out var c)) return null;
        var factors = term.Monomial.FactorArray;
        var half = new Factor[factors.Length];
        for (var i = 0; i < factors.Length; i++)
        {
            if (factors[i].Power % 2 != 0) return null;
            half[i] = factors[i] with { Power = factors[i].Power / 2 };
        }
        return new Term(c, Monomial.Create(half));
    }
}
