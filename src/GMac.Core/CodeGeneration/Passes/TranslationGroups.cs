using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Finds groups of variables along which a polynomial does not change when they are all shifted
/// by the same amount: p(v + t·1_G) = p(v) for every t, which holds exactly when the partial
/// derivatives over the group sum to zero. The coordinates of points along one axis form such a
/// group for any quantity that depends only on where the points are relative to each other
/// (a squared distance, an area, the radius of a sphere through them).
/// </summary>
internal static class TranslationGroups
{
    /// <summary>
    /// Disjoint groups of at least two of <paramref name="candidates"/>, each in the order the
    /// candidates were given (the first one is the group's anchor). Groups grow greedily: the
    /// variable that leaves the summed derivative shortest joins, as long as it does not make the
    /// sum longer, until that sum is zero (a translation direction) or nothing fits.
    /// </summary>
    public static List<List<string>> Find(Scalar polynomial, IReadOnlyList<string> candidates)
    {
        var derivatives = new Dictionary<string, Scalar>(StringComparer.Ordinal);
        foreach (var v in candidates)
        {
            var d = polynomial.Derivative(v);
            // a variable the polynomial does not read, or reads only linearly through a constant
            // slope, cannot take part in a cancelling sum with the others unless it is constant
            if (d.Terms.Count > 0) derivatives[v] = d;
        }
        var free = candidates.Where(derivatives.ContainsKey).ToList();
        var position = candidates.Select((v, i) => (v, i)).ToDictionary(p => p.v, p => p.i, StringComparer.Ordinal);
        var groups = new List<List<string>>();
        while (free.Count >= 2)
        {
            var anchor = free[0];
            free.RemoveAt(0);
            var group = new List<string> { anchor };
            var sum = derivatives[anchor];
            var sumTerms = TermTable(sum);
            while (sum.Terms.Count > 0)
            {
                // only the length of each trial sum matters: count it from the terms, and build the chosen one alone
                string? best = null;
                var bestCount = int.MaxValue;
                foreach (var v in free)
                {
                    var count = TermCountOfSum(sumTerms, derivatives[v]);
                    if (count <= sum.Terms.Count && count < bestCount)
                    {
                        best = v;
                        bestCount = count;
                    }
                }
                if (best is null) break;
                group.Add(best);
                free.Remove(best);
                sum += derivatives[best];
                sumTerms = TermTable(sum);
            }
            if (sum.Terms.Count == 0) groups.Add(group);
            else free.AddRange(group.Skip(1)); // not a translation direction: give the others back
            free.Sort((a, b) => position[a].CompareTo(position[b]));
        }
        return groups;
    }

    private static Dictionary<Monomial, Rational> TermTable(Scalar s)
    {
        var table = new Dictionary<Monomial, Rational>(s.Terms.Count);
        foreach (var t in s.TermArray) table[t.Monomial] = t.Coefficient;
        return table;
    }

    /// <summary>How many terms <c>sum + addend</c> has: shared monomials merge, and vanish where the coefficients cancel.</summary>
    private static int TermCountOfSum(Dictionary<Monomial, Rational> sum, Scalar addend)
    {
        var count = sum.Count + addend.Terms.Count;
        foreach (var t in addend.TermArray)
            if (sum.TryGetValue(t.Monomial, out var c))
                count -= c == -t.Coefficient ? 2 : 1;
        return count;
    }
}
