using GMac.Core.Numerics;

using System.Runtime.CompilerServices;

namespace GMac.Core.Symbolic;

/// <summary>
/// The exact square root r of a polynomial p = r², every atom treated as a variable. A norm of a
/// single coefficient, √(s·s), then reads |s| instead of the root of an expanded square.
/// </summary>
internal static class PolynomialSquareRoot
{
    // Beyond this the candidate's square costs more than the rule is worth.
    private const int MaxTerms = 256;

    // The simplifier rebuilds the same roots in every round; scalars are interned, so one answer per scalar.
    private static readonly ConditionalWeakTable<Scalar, Scalar?> Known = new();

    /// <summary>
    /// The terms of p whose coefficient is a positive rational square and whose powers are all even
    /// are the candidate root's squares; the cross term with the first of them fixes each sign.
    /// The candidate is squared and compared, so a false answer only means no root was found.
    /// </summary>
    public static bool TryRoot(Scalar p, out Scalar root)
    {
        root = Known.GetValue(p, Find) ?? Scalar.Zero;
        return !Scalar.IsZero(root);
    }

    private static Scalar? Find(Scalar p)
    {
        var terms = p.TermArray;
        if (terms.Length < 3 || terms.Length > MaxTerms) return null;
        var halves = new List<Term>();
        foreach (var term in terms)
            if (HalfOf(term) is { } half) halves.Add(half);
        var k = halves.Count;
        if (k < 2 || (long)k * (k + 1) / 2 < terms.Length) return null;

        var byMonomial = new Dictionary<Monomial, Rational>(terms.Length);
        foreach (var term in terms) byMonomial[term.Monomial] = term.Coefficient;
        var first = Scalar.FromTerm(halves[0].Coefficient, halves[0].Monomial);
        var rootTerms = new List<Term>(k) { halves[0] };
        for (var i = 1; i < k; i++)
        {
            var cross = (first * Scalar.FromTerm(Rational.One, halves[i].Monomial)).TermArray[0].Monomial;
            if (!byMonomial.TryGetValue(cross, out var coefficient) || coefficient.IsZero) return null;
            rootTerms.Add(coefficient.Sign < 0 ? halves[i] with { Coefficient = -halves[i].Coefficient } : halves[i]);
        }
        var candidate = Scalar.FromTerms(rootTerms);
        return candidate * candidate == p ? candidate : null;
    }

    internal static Term? HalfOf(Term term)
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
