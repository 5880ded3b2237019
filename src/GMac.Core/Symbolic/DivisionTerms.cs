using GMac.Core.Numerics;

namespace GMac.Core.Symbolic;

/// <summary>
/// What the multivariate divisions of the inverse-cancellation rewrites share besides the running
/// dividend (<see cref="DividendTerms"/>): the leading term of a divisor, and the lexicographic order
/// on monomials with every atom as a variable.
/// </summary>
internal static class DivisionTerms
{
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
