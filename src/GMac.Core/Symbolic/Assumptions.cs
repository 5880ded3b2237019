using System.Collections.Immutable;
using System.Text;
using GMac.Core.Numerics;

namespace GMac.Core.Symbolic;

/// <summary>
/// What is known about the variables of an expression: per-variable bounds (from the DSL's
/// AssumeMin/AssumeMax) and side relations. Immutable; <see cref="Key"/> is its canonical text.
/// </summary>
public sealed class Assumptions
{
    private readonly ImmutableSortedDictionary<string, (Rational? Min, Rational? Max)> _bounds;

    private Assumptions(ImmutableSortedDictionary<string, (Rational? Min, Rational? Max)> bounds, SideRelations relations)
    {
        _bounds = bounds;
        Relations = relations;
        Key = BuildKey();
    }

    /// <summary>No bounds; only the Pythagorean identity, which always holds.</summary>
    public static Assumptions None { get; } =
        new(ImmutableSortedDictionary.Create<string, (Rational?, Rational?)>(StringComparer.Ordinal), SideRelations.Trigonometric);

    public SideRelations Relations { get; }

    /// <summary>Canonical text of the bounds and relations, for cache keys.</summary>
    public string Key { get; }

    public IEnumerable<string> BoundedVariables => _bounds.Keys;

    public Rational? MinimumOf(string variable) => _bounds.TryGetValue(variable, out var b) ? b.Min : null;
    public Rational? MaximumOf(string variable) => _bounds.TryGetValue(variable, out var b) ? b.Max : null;

    /// <summary>Adds variable ≥ minimum (keeping the tighter bound if one exists).</summary>
    public Assumptions WithMinimum(string variable, Rational minimum)
    {
        var (min, max) = _bounds.TryGetValue(variable, out var b) ? b : (null, null);
        var tighter = min is { } m && m > minimum ? m : minimum;
        return WithBounds(variable, tighter, max);
    }

    /// <summary>Adds variable ≤ maximum (keeping the tighter bound if one exists).</summary>
    public Assumptions WithMaximum(string variable, Rational maximum)
    {
        var (min, max) = _bounds.TryGetValue(variable, out var b) ? b : (null, null);
        var tighter = max is { } m && m < maximum ? m : maximum;
        return WithBounds(variable, min, tighter);
    }

    public Assumptions WithBounds(string variable, Rational? minimum, Rational? maximum)
    {
        ArgumentNullException.ThrowIfNull(variable);
        if (minimum is { } lo && maximum is { } hi && lo > hi)
            throw new ArgumentException($"The bounds of '{variable}' are empty: minimum {lo} exceeds maximum {hi}.", nameof(maximum));
        return new Assumptions(_bounds.SetItem(variable, (minimum, maximum)), Relations);
    }

    public Assumptions WithRelation(Scalar left, Scalar right, Scalar eliminate) =>
        new(_bounds, Relations.With(left, right, eliminate));

    public Assumptions WithRelations(SideRelations relations) => new(_bounds, relations);

    public Interval BoundsOf(string variable)
    {
        if (!_bounds.TryGetValue(variable, out var b)) return Interval.Everything;
        var lower = b.Min is { } lo ? Interval.Exactly(lo).Lower : double.NegativeInfinity;
        var upper = b.Max is { } hi ? Interval.Exactly(hi).Upper : double.PositiveInfinity;
        return new Interval(lower, upper);
    }

    /// <summary>A guaranteed enclosure of the values of <paramref name="value"/> under these bounds.</summary>
    public Interval BoundsOf(Scalar value)
    {
        ArgumentNullException.ThrowIfNull(value);
        return BoundsOf(value, new Dictionary<Atom, Interval>());
    }

    private Interval BoundsOf(Scalar value, Dictionary<Atom, Interval> memo)
    {
        var sum = new Interval(0, 0);
        foreach (var term in value.TermArray)
        {
            var product = Interval.Exactly(term.Coefficient);
            foreach (var factor in term.Monomial.FactorArray)
                product *= BoundsOf(factor.Atom, memo).Power(factor.Power);
            sum += product;
        }
        return sum;
    }

    private Interval BoundsOf(Atom atom, Dictionary<Atom, Interval> memo)
    {
        if (memo.TryGetValue(atom, out var known)) return known;
        var a = atom.ArgumentArray;
        var result = atom.Kind switch
        {
            AtomKind.Variable => BoundsOf(atom.Name),
            AtomKind.Pi => new Interval(Math.BitDecrement(Math.PI), Math.BitIncrement(Math.PI)),
            AtomKind.Sin or AtomKind.Cos => new Interval(-1, 1),
            AtomKind.Tan => Interval.Everything,
            AtomKind.Sqrt => SqrtBounds(BoundsOf(a[0], memo)),
            AtomKind.Exp => ExpBounds(BoundsOf(a[0], memo)),
            AtomKind.Log => LogBounds(BoundsOf(a[0], memo)),
            AtomKind.Atan2 => Atan2Bounds(BoundsOf(a[0], memo)),
            AtomKind.Abs => BoundsOf(a[0], memo).Abs(),
            AtomKind.Pow => BoundsOf(a[0], memo).IsPositive ? Interval.NonNegative : Interval.Everything,
            AtomKind.Inverse => BoundsOf(a[0], memo).Reciprocal(),
            AtomKind.Cosh => new Interval(1, double.PositiveInfinity),
            _ => Interval.Everything,
        };
        memo[atom] = result;
        return result;
    }

    private static Interval SqrtBounds(Interval x)
    {
        if (x.Upper < 0) return Interval.NonNegative; // undefined in the reals; only the sign matters here
        var lower = x.Lower <= 0 ? 0 : Math.Max(0, Math.BitDecrement(Math.Sqrt(x.Lower)));
        return new Interval(lower, Math.BitIncrement(Math.Sqrt(x.Upper)));
    }

    private static Interval ExpBounds(Interval x) =>
        new(Math.Max(0, Math.BitDecrement(Math.Exp(x.Lower))), Math.BitIncrement(Math.Exp(x.Upper)));

    private static Interval LogBounds(Interval x) =>
        x.Upper <= 0
            ? Interval.Everything
            : new Interval(x.Lower > 0 ? Math.BitDecrement(Math.Log(x.Lower)) : double.NegativeInfinity, Math.BitIncrement(Math.Log(x.Upper)));

    private static Interval Atan2Bounds(Interval y)
    {
        var pi = Math.BitIncrement(Math.PI);
        return y.IsNonNegative ? new Interval(0, pi) : y.IsNonPositive ? new Interval(-pi, 0) : new Interval(-pi, pi);
    }

    private string BuildKey()
    {
        var text = new StringBuilder();
        foreach (var (name, (min, max)) in _bounds)
            text.Append(name).Append(" in [").Append(min?.ToString() ?? "-inf").Append(", ").Append(max?.ToString() ?? "inf").Append("]; ");
        text.Append(Relations);
        return text.ToString();
    }

    public override string ToString() => Key;
}
