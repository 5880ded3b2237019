using GMac.Core.Numerics;

namespace GMac.Core.Symbolic;

/// <summary>
/// What the multivariate divisions of the inverse-cancellation rewrites share: a dividend kept as a
/// table of terms by monomial (monomials are interned, so keys compare by reference) that each step
/// updates in place, and the lexicographic order on monomials with every atom as a variable.
/// </summary>
internal static class DivisionTerms
{
    public static Dictionary<Monomial, Rational> Table(Scalar s)
    {
        var table = new Dictionary<Monomial, Rational>(s.Terms.Count * 2);
        foreach (var t in s.Terms) table[t.Monomial] = t.Coefficient;
        return table;
    }

    /// <summary>
    /// table −= t·s, where t·lead (lead a term of s) is the table's term <paramref name="top"/>: that
    /// one cancels exactly and is removed, the other products are merged in.
    /// </summary>
    public static void SubtractMultiple(Dictionary<Monomial, Rational> table, Term t, Scalar s, Monomial lead, Monomial top)
    {
        table.Remove(top);
        foreach (var u in s.Terms)
        {
            if (ReferenceEquals(u.Monomial, lead)) continue;
            var m = t.Monomial * u.Monomial;
            var product = t.Coefficient * u.Coefficient;
            var c = table.TryGetValue(m, out var have) ? have - product : -product;
            if (c.IsZero) table.Remove(m);
            else table[m] = c;
        }
    }

    /// <summary>The table's greatest term under <paramref name="compare"/>.</summary>
    public static Term Leading(Dictionary<Monomial, Rational> table, Func<Monomial, Monomial, int> compare)
    {
        Monomial? best = null;
        var coefficient = Rational.Zero;
        foreach (var (m, c) in table)
        {
            if (best is null || compare(m, best) > 0)
            {
                best = m;
                coefficient = c;
            }
        }
        return new Term(coefficient, best!);
    }

    /// <summary>The greatest of the terms under <paramref name="compare"/>.</summary>
    public static Term Leading(IReadOnlyList<Term> terms, Func<Monomial, Monomial, int> compare)
    {
        var best = terms[0];
        for (var i = 1; i < terms.Count; i++)
            if (compare(terms[i].Monomial, best.Monomial) > 0) best = terms[i];
        return best;
    }

    /// <summary>
    /// Compares powers atom by atom from the greatest atom down, an atom missing from one side having
    /// power 0 there. Factors are sorted by atom, ascending, so walking both lists from the end visits
    /// the union of their atoms in descending order.
    /// </summary>
    public static int CompareDescendingAtoms(Monomial a, Monomial b)
    {
        var x = a.Factors;
        var y = b.Factors;
        int i = x.Count - 1, j = y.Count - 1;
        while (i >= 0 || j >= 0)
        {
            var order = i < 0 ? -1 : j < 0 ? 1 : Atom.Compare(x[i].Atom, y[j].Atom);
            int c;
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
}
