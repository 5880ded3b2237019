using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Rewrites;

/// <summary>
/// Multivariate division with remainder, b = q·s + r, in a lexicographic order whose first atom
/// is chosen by the caller (every atom, sin and inverses included, acts as a variable). No term
/// of r is divisible by the leading term of s, so r is the part of b that s cannot absorb.
/// </summary>
internal static class PolynomialRemainder
{
    private const int MaxSteps = 4_000;

    /// <returns>false when the division would take too many steps.</returns>
    public static bool TryDivide(Scalar b, Scalar s, Atom first, out Scalar quotient, out Scalar remainder)
    {
        quotient = Scalar.Zero;
        remainder = b;
        if (Scalar.IsZero(s) || Scalar.IsZero(b)) return false;
        var lead = Leading(s.Terms, first);
        // The dividend's remaining terms by monomial (monomials are interned, so keys compare by
        // reference): each step updates a few entries instead of building a new canonical sum.
        var rest = new Dictionary<Monomial, Rational>(b.Terms.Count * 2);
        foreach (var t in b.Terms) rest[t.Monomial] = t.Coefficient;
        var q = new List<Term>();
        var r = new List<Term>();
        for (var step = 0; rest.Count > 0; step++)
        {
            if (step == MaxSteps) return false;
            var top = Leading(rest, first);
            var factor = Divide(top.Monomial, lead.Monomial);
            rest.Remove(top.Monomial);
            if (factor is null)
            {
                r.Add(top);
                continue;
            }
            var t = new Term(top.Coefficient / lead.Coefficient, factor);
            q.Add(t);
            // rest −= t·s; the leading product cancels top, already removed.
            foreach (var u in s.Terms)
            {
                if (ReferenceEquals(u.Monomial, lead.Monomial)) continue;
                var m = factor * u.Monomial;
                var c = rest.TryGetValue(m, out var have) ? have - t.Coefficient * u.Coefficient : -(t.Coefficient * u.Coefficient);
                if (c.IsZero) rest.Remove(m);
                else rest[m] = c;
            }
        }
        quotient = Scalar.FromTerms(q);
        remainder = Scalar.FromTerms(r);
        return true;
    }

    private static Term Leading(IReadOnlyList<Term> terms, Atom first)
    {
        var best = terms[0];
        for (var i = 1; i < terms.Count; i++)
            if (Compare(terms[i].Monomial, best.Monomial, first) > 0) best = terms[i];
        return best;
    }

    private static Term Leading(Dictionary<Monomial, Rational> terms, Atom first)
    {
        Monomial? best = null;
        var coefficient = Rational.Zero;
        foreach (var (m, c) in terms)
        {
            if (best is null || Compare(m, best, first) > 0)
            {
                best = m;
                coefficient = c;
            }
        }
        return new Term(coefficient, best!);
    }

    private static int Power(Monomial m, Atom atom)
    {
        foreach (var f in m.Factors)
            if (ReferenceEquals(f.Atom, atom)) return f.Power;
        return 0;
    }

    /// <summary>The power of <paramref name="first"/> decides, then the atoms in descending canonical order.</summary>
    private static int Compare(Monomial a, Monomial b, Atom first)
    {
        var c = Power(a, first).CompareTo(Power(b, first));
        if (c != 0) return c;
        // Factors are sorted by atom, ascending: walking both lists from the end visits the union of
        // their atoms in descending order, an atom missing from one side having power 0 there.
        var x = a.Factors;
        var y = b.Factors;
        int i = x.Count - 1, j = y.Count - 1;
        while (i >= 0 || j >= 0)
        {
            var order = i < 0 ? -1 : j < 0 ? 1 : Atom.Compare(x[i].Atom, y[j].Atom);
            if (order > 0)
            {
                c = x[i].Power.CompareTo(0);
                i--;
            }
            else if (order < 0)
            {
                c = 0.CompareTo(y[j].Power);
                j--;
            }
            else
            {
                c = x[i].Power.CompareTo(y[j].Power);
                i--;
                j--;
            }
            if (c != 0) return c;
        }
        return 0;
    }

    /// <summary>m / d when d's powers do not exceed m's (only positive powers divide).</summary>
    private static Monomial? Divide(Monomial m, Monomial d)
    {
        var powers = m.Factors.ToDictionary(f => f.Atom, f => f.Power);
        foreach (var f in d.Factors)
        {
            var have = powers.GetValueOrDefault(f.Atom);
            if (f.Power <= 0 || have < f.Power) return null;
            powers[f.Atom] = have - f.Power;
        }
        return Monomial.Create(powers.Where(kv => kv.Value != 0).Select(kv => new Factor(kv.Key, kv.Value)));
    }

    /// <summary>Atoms that may lead the order: those of s with a positive power.</summary>
    public static IEnumerable<Atom> Candidates(Scalar s) =>
        s.Terms.SelectMany(t => t.Monomial.Factors).Where(f => f.Power > 0).Select(f => f.Atom).Distinct().Order();

    public static Rational LeadCoefficient(Scalar s) => s.Terms[0].Coefficient;
}
