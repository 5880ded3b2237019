using GMac.Core.Numerics;

namespace GMac.Core.Symbolic;

/// <summary>
/// Accumulates a sum of scalars and products of scalars without creating (and interning) every
/// partial sum: like terms are combined by monomial and the canonical scalar is built once at the end.
/// Use it for long sums such as the coefficients of a bilinear product. Not thread-safe.
/// </summary>
public sealed class ScalarSumBuilder
{
    private readonly Dictionary<Monomial, Rational> _terms = new();

    public int TermCount => _terms.Count;

    public void Add(Scalar value) => Add(value, Rational.One);

    public void Add(Scalar value, Rational factor)
    {
        ArgumentNullException.ThrowIfNull(value);
        if (factor.IsZero) return;
        foreach (var term in value.TermArray) Accumulate(term.Monomial, factor.IsOne ? term.Coefficient : term.Coefficient * factor);
    }

    public void Add(Term term)
    {
        if (!term.Coefficient.IsZero) Accumulate(term.Monomial, term.Coefficient);
    }

    public void Subtract(Scalar value) => Add(value, Rational.MinusOne);

    /// <summary>Adds factor · a · b, expanding the product term by term.</summary>
    public void AddProduct(Scalar a, Scalar b, Rational factor)
    {
        ArgumentNullException.ThrowIfNull(a);
        ArgumentNullException.ThrowIfNull(b);
        if (factor.IsZero) return;
        foreach (var s in a.TermArray)
        {
            var c = factor.IsOne ? s.Coefficient : s.Coefficient * factor;
            foreach (var t in b.TermArray) Accumulate(s.Monomial * t.Monomial, c * t.Coefficient);
        }
    }

    public void AddProduct(Scalar a, Scalar b) => AddProduct(a, b, Rational.One);

    public Scalar ToScalar()
    {
        var list = new List<Term>(_terms.Count);
        foreach (var (monomial, coefficient) in _terms)
            if (!coefficient.IsZero) list.Add(new Term(coefficient, monomial));
        return Scalar.FromOwnedTerms(list);
    }

    public void Clear() => _terms.Clear();

    private void Accumulate(Monomial monomial, Rational coefficient)
    {
        _terms[monomial] = _terms.TryGetValue(monomial, out var previous) ? previous + coefficient : coefficient;
    }
}
