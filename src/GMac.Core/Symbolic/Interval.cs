using GMac.Core.Numerics;

namespace GMac.Core.Symbolic;

/// <summary>
/// A closed real interval [Lower, Upper] (infinite ends allowed) for sign analysis. Arithmetic
/// rounds outward by one ulp whenever a result may be inexact, so a computed interval always
/// contains the true range; results that are exactly zero stay exactly zero.
/// </summary>
public readonly record struct Interval(double Lower, double Upper)
{
    public static Interval Everything { get; } = new(double.NegativeInfinity, double.PositiveInfinity);
    public static Interval NonNegative { get; } = new(0, double.PositiveInfinity);

    /// <summary>The tightest double interval known to contain <paramref name="value"/>, keeping its sign.</summary>
    public static Interval Exactly(Rational value)
    {
        var d = value.ToDouble();
        if (double.IsFinite(d) && Rational.FromDouble(d) == value) return new Interval(d, d);
        // The conversion may be off by more than one ulp (two roundings and a division), so widen by two.
        var lower = double.IsFinite(d) ? Math.BitDecrement(Math.BitDecrement(d)) : d > 0 ? double.MaxValue : double.NegativeInfinity;
        var upper = double.IsFinite(d) ? Math.BitIncrement(Math.BitIncrement(d)) : d > 0 ? double.PositiveInfinity : -double.MaxValue;
        if (value.Sign > 0) lower = Math.Max(lower, 0);
        if (value.Sign < 0) upper = Math.Min(upper, 0);
        return new Interval(lower, upper);
    }

    public bool IsNonNegative => Lower >= 0;
    public bool IsPositive => Lower > 0;
    public bool IsNonPositive => Upper <= 0;
    public bool IsNegative => Upper < 0;
    public bool Contains(double value) => Lower <= value && value <= Upper;

    public static Interval operator +(Interval a, Interval b) =>
        new(Down(a.Lower + b.Lower, a.Lower, b.Lower), Up(a.Upper + b.Upper, a.Upper, b.Upper));

    public static Interval operator -(Interval a) => new(-a.Upper, -a.Lower);

    public static Interval operator *(Interval a, Interval b)
    {
        double lower = double.PositiveInfinity, upper = double.NegativeInfinity;
        foreach (var x in (ReadOnlySpan<double>)[a.Lower, a.Upper])
        foreach (var y in (ReadOnlySpan<double>)[b.Lower, b.Upper])
        {
            // 0·∞ counts as 0: the infinite end is never attained.
            var p = x == 0 || y == 0 ? 0 : x * y;
            lower = Math.Min(lower, Down(p, x, y));
            upper = Math.Max(upper, Up(p, x, y));
        }
        return new Interval(lower, upper);
    }

    public Interval Reciprocal()
    {
        // Clamped at zero so the sign survives rounding near 1/∞.
        if (Lower > 0) return new Interval(Math.Max(0, Math.BitDecrement(1 / Upper)), Math.BitIncrement(1 / Lower));
        if (Upper < 0) return new Interval(Math.BitDecrement(1 / Upper), Math.Min(-0.0, Math.BitIncrement(1 / Lower)));
        return Everything;
    }

    public Interval Power(int n)
    {
        if (n == 0) return new Interval(1, 1);
        if (n < 0) return Power(-n).Reciprocal();
        if (n % 2 == 1)
        {
            var result = this;
            for (var i = 1; i < n; i++) result *= this;
            return result;
        }
        var magnitude = Abs();
        var even = magnitude;
        for (var i = 1; i < n; i++) even *= magnitude;
        return even;
    }

    public Interval Abs() =>
        Lower >= 0 ? this : Upper <= 0 ? -this : new Interval(0, Math.Max(-Lower, Upper));

    // An operation with a zero operand (x + 0, x · 0) or an infinite result is exact.
    private static double Down(double value, double x, double y) =>
        double.IsInfinity(value) || x == 0 || y == 0 ? value : Math.BitDecrement(value);

    private static double Up(double value, double x, double y) =>
        double.IsInfinity(value) || x == 0 || y == 0 ? value : Math.BitIncrement(value);

    public override string ToString() => $"[{Lower}, {Upper}]";
}
