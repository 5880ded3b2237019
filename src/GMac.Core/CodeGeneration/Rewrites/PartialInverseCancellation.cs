using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Rewrites;

/// <summary>
/// Norm cancellation with a remainder: in B·(1/s) + R, the part of B that is a polynomial multiple
/// of s leaves the fraction, B = Q·s + B' gives Q + B'·(1/s) + R. A rejection or a sandwich by
/// an unnormalized vector divides by its squared norm |a|², and the products it divides often
/// carry |a|² in some terms only (ω (p·a) a + γ |a|² (a × p)): exact cancellation needs all of
/// B, this takes what it can. Kept only when the expression gets fewer terms.
/// </summary>
public static class PartialInverseCancellation
{
    /// <summary>Larger cofactors and divisors are left alone: division costs grow with the product of their sizes.</summary>
    private const int MaxCofactorTerms = 48;
    private const int MaxDivisorTerms = 8;

    public static Scalar Apply(Scalar e)
    {
        // Every inverse, nested ones included: a quotient can bring one up from inside a divisor,
        // and it is then taken in its turn. Until then it has no cofactor, so it is skipped unsplit.
        foreach (var atom in e.Atoms().Where(a => a.Kind == AtomKind.Inverse).Order().ToArray())
        {
            if (!e.FactorAtoms.Contains(atom)) continue;
            var (cofactor, rest) = Split(e, atom);
            var s = atom.Arguments[0];
            if (cofactor.Terms.Count < 2 || cofactor.Terms.Count > MaxCofactorTerms || s.Terms.Count > MaxDivisorTerms) continue;
            Scalar? best = null;
            foreach (var first in PolynomialRemainder.Candidates(s))
            {
                if (!PolynomialRemainder.CanDivide(cofactor, s, first)) continue; // the quotient would be zero
                if (!PolynomialRemainder.TryDivide(cofactor, s, first, out var q, out var r) || Scalar.IsZero(q)) continue;
                var candidate = q + r * atom.AsScalar() + rest;
                if (candidate.Terms.Count < (best ?? e).Terms.Count) best = candidate;
            }
            if (best is not null) e = best;
        }
        return e;
    }

    /// <summary>e = cofactor·atom + rest, where rest has no positive power of the atom.</summary>
    private static (Scalar Cofactor, Scalar Remaining) Split(Scalar e, Atom atom)
    {
        var cofactor = new List<Term>();
        var rest = new List<Term>();
        foreach (var t in e.TermArray)
        {
            var power = t.Monomial.PowerOf(atom);
            if (power > 0) cofactor.Add(new Term(t.Coefficient, Monomial.WithPower(t.Monomial, atom, power - 1)));
            else rest.Add(t);
        }
        return (Scalar.FromOwnedTerms(cofactor), Scalar.FromOwnedTerms(rest));
    }
}
