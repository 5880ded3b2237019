using System.Globalization;
using System.Numerics;

namespace GMac.Core.Numerics;

/// <summary>
/// An exact rational number p/q kept in lowest terms with q &gt; 0.
/// Used for basis-blade product tables and the constant parts of symbolic scalars,
/// so that no rounding enters before code is emitted.
/// </summary>
public readonly struct Rational : IEquatable<Rational>, IComparable<Rational>
{
    public static readonly Rational Zero = new(BigInteger.Zero, BigInteger.One, true);
    public static readonly Rational One = new(BigInteger.One, BigInteger.One, true);
    public static readonly Rational MinusOne = new(BigInteger.MinusOne, BigInteger.One, true);

    private readonly BigInteger _numerator;
    private readonly BigInteger _denominatorMinusOne; // default(Rational) must mean 0/1

    public BigInteger Numerator => _numerator;
    public BigInteger Denominator => _denominatorMinusOne + BigInteger.One;

    private Rational(BigInteger numerator, BigInteger denominator, bool _)
    {
        _numerator = numerator;
        _denominatorMinusOne = denominator - BigInteger.One;
    }

    public Rational(BigInteger numerator, BigInteger denominator)
    {
        if (denominator.IsZero)
            throw new DivideByZeroException("A rational number cannot have a zero denominator.");
        if (denominator.Sign < 0)
        {
            numerator = -numerator;
            denominator = -denominator;
        }
        var gcd = BigInteger.GreatestCommonDivisor(numerator, denominator);
        if (!gcd.IsOne && !gcd.IsZero)
        {
            numerator /= gcd;
            denominator /= gcd;
        }
        if (numerator.IsZero) denominator = BigInteger.One;
        _numerator = numerator;
        _denominatorMinusOne = denominator - BigInteger.One;
    }

    public static implicit operator Rational(int value) => new(value, BigInteger.One, true);
    public static implicit operator Rational(long value) => new(value, BigInteger.One, true);
    public static implicit operator Rational(BigInteger value) => new(value, BigInteger.One, true);

    public bool IsZero => _numerator.IsZero;
    public bool IsOne => _numerator.IsOne && _denominatorMinusOne.IsZero;
    public bool IsInteger => _denominatorMinusOne.IsZero;
    public int Sign => _numerator.Sign;

    public static Rational operator +(Rational a, Rational b) =>
        a.IsInteger && b.IsInteger
            ? new Rational(a._numerator + b._numerator, BigInteger.One, true)
            : new Rational(a._numerator * b.Denominator + b._numerator * a.Denominator, a.Denominator * b.Denominator);

    public static Rational operator -(Rational a, Rational b) => a + (-b);
    public static Rational operator -(Rational a) => new(-a._numerator, a.Denominator, true);

    public static Rational operator *(Rational a, Rational b) =>
        a.IsInteger && b.IsInteger
            ? new Rational(a._numerator * b._numerator, BigInteger.One, true)
            : new Rational(a._numerator * b._numerator, a.Denominator * b.Denominator);

    public static Rational operator /(Rational a, Rational b)
    {
        if (b.IsZero) throw new DivideByZeroException("Division of a rational number by zero.");
        return new Rational(a._numerator * b.Denominator, a.Denominator * b._numerator);
    }

    public Rational Reciprocal() => One / this;
    public Rational Abs() => Sign < 0 ? -this : this;

    /// <summary>Integer power; negative exponents give the reciprocal power.</summary>
    public Rational Pow(int exponent)
    {
        if (exponent == 0) return One;
        if (exponent < 0) return Reciprocal().Pow(-exponent);
        return new Rational(BigInteger.Pow(_numerator, exponent), BigInteger.Pow(Denominator, exponent), true);
    }

    /// <summary>The exact square root when numerator and denominator are both perfect squares.</summary>
    public bool TryExactSqrt(out Rational root)
    {
        root = Zero;
        if (Sign < 0) return false;
        if (!TryIntegerSqrt(_numerator, out var n) || !TryIntegerSqrt(Denominator, out var d)) return false;
        root = new Rational(n, d, true);
        return true;
    }

    private static bool TryIntegerSqrt(BigInteger value, out BigInteger root)
    {
        if (value.IsZero) { root = BigInteger.Zero; return true; }
        // Newton iteration from a float estimate, then exact correction.
        var x = new BigInteger(Math.Sqrt((double)value));
        for (var i = 0; i < 100; i++)
        {
            var next = (x + value / BigInteger.Max(x, BigInteger.One)) >> 1;
            if (BigInteger.Abs(next - x) <= BigInteger.One) { x = next; break; }
            x = next;
        }
        while (x * x > value) x -= 1;
        while ((x + 1) * (x + 1) <= value) x += 1;
        root = x;
        return x * x == value;
    }

    public double ToDouble()
    {
        if (IsInteger) return (double)_numerator;
        var value = (double)_numerator / (double)Denominator;
        if (double.IsNormal(value)) return value;
        // A part beyond the range of a double, or a subnormal result: take an integer quotient of
        // 66 significant bits (plus a sticky bit for a non-zero remainder) and scale it by 2^-shift.
        var numerator = BigInteger.Abs(_numerator);
        var denominator = Denominator;
        var shift = 66 - (numerator.GetBitLength() - denominator.GetBitLength());
        var quotient = shift >= 0
            ? BigInteger.DivRem(numerator << (int)shift, denominator, out var remainder)
            : BigInteger.DivRem(numerator, denominator << (int)-shift, out remainder);
        if (!remainder.IsZero) quotient |= BigInteger.One;
        var magnitude = shift > 2000 ? 0.0 : shift < -2000 ? double.PositiveInfinity : Math.ScaleB((double)quotient, (int)-shift);
        return Sign < 0 ? -magnitude : magnitude;
    }

    /// <summary>The exact value of a finite double (every double is a dyadic rational).</summary>
    public static Rational FromDouble(double value)
    {
        if (!double.IsFinite(value))
            throw new ArgumentOutOfRangeException(nameof(value), value, "Only finite numbers have an exact rational value.");
        if (value == 0) return Zero;
        var bits = BitConverter.DoubleToInt64Bits(value);
        var negative = bits < 0;
        var exponent = (int)((bits >> 52) & 0x7FF);
        var mantissa = bits & 0xFFFFFFFFFFFFFL;
        if (exponent == 0) exponent++; else mantissa |= 1L << 52;
        exponent -= 1075;
        BigInteger num = mantissa;
        var result = exponent >= 0
            ? new Rational(num << exponent, BigInteger.One)
            : new Rational(num, BigInteger.One << -exponent);
        return negative ? -result : result;
    }

    /// <summary>Parses "3", "-2/7", "1.25" or "2.5e-3" exactly (decimal exponents up to ±<see cref="MaxDecimalExponent"/>).</summary>
    public static Rational Parse(string text)
    {
        if (TryParse(text, out var value)) return value;
        throw new FormatException($"'{text}' is not a rational number.");
    }

    public static bool TryParse(string? text, out Rational value)
    {
        value = Zero;
        if (string.IsNullOrWhiteSpace(text)) return false;
        text = text.Trim();
        var slash = text.IndexOf('/');
        if (slash >= 0)
        {
            if (!TryParse(text[..slash], out var n) || !TryParse(text[(slash + 1)..], out var d) || d.IsZero) return false;
            value = n / d;
            return true;
        }
        long exponent = 0;
        var e = text.IndexOfAny(['e', 'E']);
        if (e >= 0)
        {
            if (!int.TryParse(text[(e + 1)..], NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out var written)) return false;
            exponent = written;
            text = text[..e];
        }
        var dot = text.IndexOf('.');
        if (dot >= 0)
        {
            exponent -= text.Length - dot - 1;
            text = text.Remove(dot, 1);
        }
        // 10^exponent is built exactly, so an exponent like 1e999999999 would take unbounded time and memory.
        if (Math.Abs(exponent) > MaxDecimalExponent) return false;
        if (text.Length == 0 || text is "-" or "+") return false;
        if (!BigInteger.TryParse(text, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out var digits)) return false;
        value = exponent >= 0
            ? new Rational(digits * BigInteger.Pow(10, (int)exponent), BigInteger.One)
            : new Rational(digits, BigInteger.Pow(10, (int)-exponent));
        return true;
    }

    /// <summary>
    /// The largest power of ten a decimal literal may carry (after moving its decimal point): far past
    /// the range of a double (about 1e±308), yet cheap to build exactly.
    /// </summary>
    public const int MaxDecimalExponent = 1000;

    public bool Equals(Rational other) => _numerator == other._numerator && _denominatorMinusOne == other._denominatorMinusOne;
    public override bool Equals(object? obj) => obj is Rational r && Equals(r);
    public override int GetHashCode() => HashCode.Combine(_numerator, _denominatorMinusOne);
    public int CompareTo(Rational other) => (_numerator * other.Denominator).CompareTo(other._numerator * Denominator);

    public static bool operator ==(Rational a, Rational b) => a.Equals(b);
    public static bool operator !=(Rational a, Rational b) => !a.Equals(b);
    public static bool operator <(Rational a, Rational b) => a.CompareTo(b) < 0;
    public static bool operator >(Rational a, Rational b) => a.CompareTo(b) > 0;
    public static bool operator <=(Rational a, Rational b) => a.CompareTo(b) <= 0;
    public static bool operator >=(Rational a, Rational b) => a.CompareTo(b) >= 0;

    /// <summary>"p" or "p/q", the form <see cref="Parse"/> reads back.</summary>
    public override string ToString() =>
        IsInteger
            ? _numerator.ToString(CultureInfo.InvariantCulture)
            : $"{_numerator.ToString(CultureInfo.InvariantCulture)}/{Denominator.ToString(CultureInfo.InvariantCulture)}";
}
