using System.Numerics;
using GMac.Core.Numerics;

namespace GMac.Benchmarks.Accuracy;

/// <summary>
/// The math functions of generated code on exact rationals, correct to about <see cref="Bits"/>
/// significant bits: far beyond a double, so a reference computed with them has no error that
/// matters next to the errors being measured. Arithmetic stays exact; only these functions round.
/// Each returns null where the function is undefined (a negative square root, the log of zero).
/// </summary>
public static class HighPrecision
{
    public const int Bits = 200;

    private static readonly Lazy<Rational> LazyPi = new(() => Round(16 * AtanOfInverse(5) - 4 * AtanOfInverse(239)));
    private static readonly Lazy<Rational> LazyLn2 = new(() => Round(2 * Atanh(new Rational(1, 3))));

    public static Rational Pi => LazyPi.Value;

    public static Rational? Call(string function, IReadOnlyList<Rational> args) => function switch
    {
        "sqrt" => Sqrt(args[0]),
        "sin" => Sin(args[0]),
        "cos" => Cos(args[0]),
        "tan" => Cos(args[0]) is { IsZero: false } c ? Round(Sin(args[0]) / c) : null,
        "exp" => Exp(args[0]),
        "log" => Log(args[0]),
        "sinh" => Sinh(args[0]),
        "cosh" => Round((Exp(args[0]) + Exp(-args[0])) / 2),
        "abs" => args[0].Abs(),
        "atan2" => Atan2(args[0], args[1]),
        "acos" => Acos(args[0]),
        "pow" => Pow(args[0], args[1]),
        _ => throw new ArgumentException($"no high-precision version of '{function}'", nameof(function)),
    };

    /// <summary>Keeps the <see cref="Bits"/> (plus a guard) leading bits of a rational, so that long computations stay small.</summary>
    public static Rational Round(Rational x)
    {
        if (x.IsZero) return x;
        var shift = Bits + 16 - (int)(BigInteger.Abs(x.Numerator).GetBitLength() - x.Denominator.GetBitLength());
        var scaled = shift >= 0
            ? BigInteger.Divide(x.Numerator << shift, x.Denominator)
            : BigInteger.Divide(x.Numerator, x.Denominator << -shift);
        return shift >= 0 ? new Rational(scaled, BigInteger.One << shift) : new Rational(scaled << -shift, BigInteger.One);
    }

    public static Rational? Sqrt(Rational x)
    {
        if (x.Sign < 0) return null;
        if (x.IsZero) return x;
        if (x.TryExactSqrt(out var exact)) return exact;
        var guess = Math.Sqrt(x.ToDouble());
        var y = double.IsNormal(guess) ? Rational.FromDouble(guess) : Rational.One;
        for (var i = 0; i < 12; i++) y = Round((y + x / y) / 2);
        return y;
    }

    public static Rational Sin(Rational x)
    {
        var r = ReduceAngle(x);
        // Σ (−1)^k r^(2k+1) / (2k+1)!
        return Series(r, (term, n) => -term * r * r / ((2 * n) * (2 * n + 1)));
    }

    public static Rational Cos(Rational x)
    {
        var r = ReduceAngle(x);
        return Series(Rational.One, (term, n) => -term * r * r / ((2 * n - 1) * (2 * n)));
    }

    public static Rational Exp(Rational x)
    {
        // exp(x) = exp(x / 2^m)^(2^m) with |x / 2^m| < 1/2
        var halvings = 0;
        var r = x;
        while (r.Abs() > new Rational(1, 2)) { r /= 2; halvings++; }
        var y = Series(Rational.One, (term, n) => term * r / n);
        for (var i = 0; i < halvings; i++) y = Round(y * y);
        return y;
    }

    /// <summary>The odd series below 1 in magnitude (no cancellation of e^x − e^−x), else the exponentials.</summary>
    public static Rational Sinh(Rational x) =>
        x.Abs() < Rational.One ? Series(x, (term, n) => term * x * x / ((2 * n) * (2 * n + 1))) : Round((Exp(x) - Exp(-x)) / 2);

    public static Rational? Log(Rational x)
    {
        if (x.Sign <= 0) return null;
        // x = m · 2^e with m in [1/2, 1): log x = e·ln 2 + 2 atanh((m − 1)/(m + 1))
        var e = (int)(x.Numerator.GetBitLength() - x.Denominator.GetBitLength());
        var m = e >= 0 ? x / new Rational(BigInteger.One << e, BigInteger.One) : x * new Rational(BigInteger.One << -e, BigInteger.One);
        return Round(e * LazyLn2.Value + 2 * Atanh((m - 1) / (m + 1)));
    }

    public static Rational? Atan2(Rational y, Rational x)
    {
        if (x.Sign > 0) return Atan(y / x);
        if (x.Sign < 0) return y.Sign >= 0 ? Round(Atan(y / x) + Pi) : Round(Atan(y / x) - Pi);
        return y.Sign > 0 ? Pi / 2 : y.Sign < 0 ? -Pi / 2 : Rational.Zero;
    }

    /// <summary>acos x = atan2(√(1 − x²), x) on [−1, 1].</summary>
    public static Rational? Acos(Rational x) => x.Abs() > Rational.One ? null : Atan2(Sqrt(1 - x * x)!.Value, x);

    public static Rational? Pow(Rational a, Rational b)
    {
        if (b.IsInteger && BigInteger.Abs(b.Numerator) < 4096)
            return a.IsZero && b.Sign < 0 ? null : a.Pow((int)b.Numerator);
        return Log(a) is { } log ? Exp(Round(b * log)) : null;
    }

    public static Rational Atan(Rational x)
    {
        if (x.Abs() > Rational.One) return Round((x.Sign > 0 ? Pi / 2 : -Pi / 2) - Atan(Rational.One / x));
        // atan x = 2 atan(x / (1 + √(1 + x²))): two halvings bring |x| under tan(π/16)
        for (var i = 0; i < 2; i++) x = Round(x / (1 + Sqrt(1 + x * x)!.Value));
        return 4 * Series(x, (term, n) => -term * x * x * (2 * n - 1) / (2 * n + 1));
    }

    /// <summary>Σ x^(2k+1) / (2k+1), for |x| well below 1.</summary>
    private static Rational Atanh(Rational x) => Series(x, (term, n) => term * x * x * (2 * n - 1) / (2 * n + 1));

    private static Rational AtanOfInverse(int n)
    {
        var x = new Rational(1, n);
        return Series(x, (term, k) => -term * x * x * (2 * k - 1) / (2 * k + 1));
    }

    /// <summary>x − 2πk in [−π, π].</summary>
    private static Rational ReduceAngle(Rational x)
    {
        var turns = Math.Round(x.ToDouble() / (2 * Math.PI));
        return turns == 0 ? x : Round(x - new Rational(new BigInteger(turns), BigInteger.One) * 2 * Pi);
    }

    /// <summary>Sums terms t₀, t₁ = next(t₀, 1), … until they fall below 2^−(Bits + 16) of the first.</summary>
    private static Rational Series(Rational first, Func<Rational, int, Rational> next)
    {
        var sum = first;
        var term = first;
        var limit = Ldexp(first.IsZero ? Rational.One : first.Abs(), -(Bits + 16));
        for (var n = 1; n < 10_000; n++)
        {
            term = Round(next(term, n));
            if (term.Abs() < limit) break;
            sum += term;
        }
        return Round(sum);
    }

    private static Rational Ldexp(Rational x, int exponent) =>
        exponent >= 0 ? x * new Rational(BigInteger.One << exponent, BigInteger.One) : x / new Rational(BigInteger.One << -exponent, BigInteger.One);
}
