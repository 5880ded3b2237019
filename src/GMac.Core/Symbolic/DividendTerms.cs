using GMac.Core.Numerics;

namespace GMac.Core.Symbolic;

/// <summary>
/// The running dividend of a multivariate division: its terms by monomial (monomials are interned,
/// so keys compare by reference), updated in place, with a heap in the division's order so the
/// leading term is found in logarithmic rather than linear time per step. The heap may hold
/// monomials that have since cancelled; they are dropped when they reach the top.
/// </summary>
internal sealed class DividendTerms
{
    private readonly Dictionary<Monomial, Rational> _table;
    private readonly PriorityQueue<Monomial, Monomial> _heap;

    public DividendTerms(Scalar dividend, Func<Monomial, Monomial, int> compare)
    {
        _table = new Dictionary<Monomial, Rational>(dividend.TermArray.Length * 2);
        _heap = new PriorityQueue<Monomial, Monomial>(dividend.TermArray.Length * 2, Comparer<Monomial>.Create((a, b) => compare(b, a)));
        foreach (var t in dividend.TermArray)
        {
            _table[t.Monomial] = t.Coefficient;
            _heap.Enqueue(t.Monomial, t.Monomial);
        }
    }

    public int Count => _table.Count;

    /// <summary>The greatest remaining term in the order; the dividend must not be empty.</summary>
    public Term Leading()
    {
        while (true)
        {
            var m = _heap.Peek();
            if (_table.TryGetValue(m, out var c)) return new Term(c, m);
            _heap.Dequeue();
        }
    }

    public void Remove(Monomial m) => _table.Remove(m);

    /// <summary>
    /// dividend −= t·s, where t·lead (lead a term of s) is the dividend's term <paramref name="top"/>:
    /// that one cancels exactly and is removed, the other products are merged in.
    /// </summary>
    public void SubtractMultiple(Term t, Scalar s, Monomial lead, Monomial top)
    {
        _table.Remove(top);
        foreach (var u in s.TermArray)
        {
            if (ReferenceEquals(u.Monomial, lead)) continue;
            var m = t.Monomial * u.Monomial;
            var product = t.Coefficient * u.Coefficient;
            if (_table.TryGetValue(m, out var have))
            {
                var c = have - product;
                if (c.IsZero) _table.Remove(m);
                else _table[m] = c;
            }
            else
            {
                _table[m] = -product;
                _heap.Enqueue(m, m);
            }
        }
    }
}
