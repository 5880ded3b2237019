using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// The rational span of a few polynomials: whether a polynomial is a combination of them with
/// constant coefficients, and which. Rows are kept in echelon form over their leading monomials
/// (each row is reduced by the rows before it), so reducing in row order is exact.
/// </summary>
internal sealed class PolynomialSpan
{
    private readonly List<(Scalar Row, Monomial Pivot, Rational PivotCoefficient, Dictionary<int, Rational> Combination)> _rows = [];

    /// <param name="basis">The polynomials; zero and dependent ones are allowed and simply add no row.</param>
    public PolynomialSpan(IReadOnlyList<Scalar> basis)
    {
        for (var j = 0; j < basis.Count; j++)
        {
            var (rest, combination) = Reduce(basis[j]);
            if (Scalar.IsZero(rest)) continue;
            // rest = basis[j] − Σ combination·basis, so basis[j]'s own weight in the row is one
            var rowCombination = combination.ToDictionary(c => c.Key, c => -c.Value);
            rowCombination[j] = rowCombination.GetValueOrDefault(j) + Rational.One;
            var lead = rest.Terms[0];
            _rows.Add((rest, lead.Monomial, lead.Coefficient, rowCombination));
        }
    }

    /// <summary>The coefficients c with <paramref name="target"/> = Σ c_j basis_j, or null when it is not in the span.</summary>
    public Dictionary<int, Rational>? Express(Scalar target)
    {
        var (rest, combination) = Reduce(target);
        return Scalar.IsZero(rest) ? combination : null;
    }

    private (Scalar Remainder, Dictionary<int, Rational> Combination) Reduce(Scalar target)
    {
        var combination = new Dictionary<int, Rational>();
        foreach (var (row, pivot, pivotCoefficient, rowCombination) in _rows)
        {
            var c = CoefficientOf(target, pivot);
            if (c.IsZero) continue;
            var factor = c / pivotCoefficient;
            target -= Scalar.Scale(row, factor);
            foreach (var (j, w) in rowCombination) combination[j] = combination.GetValueOrDefault(j) + factor * w;
        }
        return (target, combination);
    }

    private static Rational CoefficientOf(Scalar s, Monomial m)
    {
        foreach (var t in s.Terms)
            if (ReferenceEquals(t.Monomial, m))
                return t.Coefficient;
        return Rational.Zero;
    }
}
