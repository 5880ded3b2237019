using System.Globalization;
using System.Numerics;
using GMac.Core.Numerics;

namespace GMac.Core.Symbolic;

// .NET generic math, so that Multivector<T> can be instantiated with Scalar as with double.
// Predicates are exact for constants and conservative (false) for anything symbolic.
public sealed partial class Scalar :
    INumberBase<Scalar>,
    IRootFunctions<Scalar>,
    ITrigonometricFunctions<Scalar>,
    IHyperbolicFunctions<Scalar>,
    IExponentialFunctions<Scalar>,
    ILogarithmicFunctions<Scalar>,
    IPowerFunctions<Scalar>
{
    // The canonical form is exact; radix is reported as for binary floating point.
    static int INumberBase<Scalar>.Radix => 2;

    public static Scalar AdditiveIdentity => Zero;
    public static Scalar MultiplicativeIdentity => One;

    static Scalar INumberBase<Scalar>.Abs(Scalar value) => Abs(value);

    public static bool IsZero(Scalar value) => value._terms.Length == 0;
    public static bool IsCanonical(Scalar value) => true;
    public static bool IsComplexNumber(Scalar value) => false;
    public static bool IsImaginaryNumber(Scalar value) => false;
    public static bool IsRealNumber(Scalar value) => value.IsConstant;
    public static bool IsFinite(Scalar value) => value.IsConstant;
    public static bool IsInfinity(Scalar value) => false;
    public static bool IsPositiveInfinity(Scalar value) => false;
    public static bool IsNegativeInfinity(Scalar value) => false;
    public static bool IsNaN(Scalar value) => false;
    public static bool IsSubnormal(Scalar value) => false;
    public static bool IsNormal(Scalar value) => value.TryGetConstant(out var c) && !c.IsZero;
    public static bool IsInteger(Scalar value) => value.TryGetConstant(out var c) && c.IsInteger;
    public static bool IsEvenInteger(Scalar value) => value.TryGetConstant(out var c) && c.IsInteger && c.Numerator.IsEven;
    public static bool IsOddInteger(Scalar value) => value.TryGetConstant(out var c) && c.IsInteger && !c.Numerator.IsEven;
    public static bool IsNegative(Scalar value) => value.TryGetConstant(out var c) && c.Sign < 0;

    /// <summary>As for integers and +0.0, zero counts as positive.</summary>
    public static bool IsPositive(Scalar value) => value.TryGetConstant(out var c) && c.Sign >= 0;

    public static Scalar MaxMagnitude(Scalar x, Scalar y) => CompareMagnitudes(x, y) >= 0 ? x : y;
    public static Scalar MaxMagnitudeNumber(Scalar x, Scalar y) => MaxMagnitude(x, y);
    public static Scalar MinMagnitude(Scalar x, Scalar y) => CompareMagnitudes(x, y) <= 0 ? x : y;
    public static Scalar MinMagnitudeNumber(Scalar x, Scalar y) => MinMagnitude(x, y);

    private static int CompareMagnitudes(Scalar x, Scalar y)
    {
        if (ReferenceEquals(x, y)) return 0;
        if (x.TryGetConstant(out var a) && y.TryGetConstant(out var b)) return a.Abs().CompareTo(b.Abs());
        throw new NotSupportedException($"The magnitudes of the symbolic scalars '{x}' and '{y}' cannot be compared without values.");
    }

    // ---- conversions ----------------------------------------------------------------------

    public static Scalar CreateFromDouble(double value) =>
        double.IsFinite(value)
            ? Constant(Rational.FromDouble(value))
            : throw new OverflowException($"{value} has no exact symbolic value.");

    /// <summary>Exact conversion from any built-in number (doubles and decimals by their exact value).</summary>
    public static Scalar CreateChecked<TOther>(TOther value) where TOther : INumberBase<TOther> => Create(value);

    public static Scalar CreateSaturating<TOther>(TOther value) where TOther : INumberBase<TOther> => Create(value);

    public static Scalar CreateTruncating<TOther>(TOther value) where TOther : INumberBase<TOther> => Create(value);

    private static Scalar Create<TOther>(TOther value) where TOther : INumberBase<TOther>
    {
        if (TryConvertFrom(value, out var result)) return result;
        if (TOther.TryConvertToChecked<Scalar>(value, out var converted)) return converted;
        throw new NotSupportedException($"Values of type {typeof(TOther).Name} cannot be converted to a symbolic scalar.");
    }

    static bool INumberBase<Scalar>.TryConvertFromChecked<TOther>(TOther value, out Scalar result) => TryConvertFrom(value, out result);
    static bool INumberBase<Scalar>.TryConvertFromSaturating<TOther>(TOther value, out Scalar result) => TryConvertFrom(value, out result);
    static bool INumberBase<Scalar>.TryConvertFromTruncating<TOther>(TOther value, out Scalar result) => TryConvertFrom(value, out result);
    static bool INumberBase<Scalar>.TryConvertToChecked<TOther>(Scalar value, out TOther result) => TryConvertTo(value, out result);
    static bool INumberBase<Scalar>.TryConvertToSaturating<TOther>(Scalar value, out TOther result) => TryConvertTo(value, out result);
    static bool INumberBase<Scalar>.TryConvertToTruncating<TOther>(Scalar value, out TOther result) => TryConvertTo(value, out result);

    private static bool TryConvertFrom<TOther>(TOther value, out Scalar result)
    {
        Rational? exact = value switch
        {
            int v => v,
            long v => v,
            short v => (int)v,
            sbyte v => (int)v,
            byte v => (int)v,
            ushort v => (int)v,
            uint v => (long)v,
            ulong v => new BigInteger(v),
            BigInteger v => v,
            Int128 v => (BigInteger)v,
            UInt128 v => (BigInteger)v,
            decimal v => Rational.Parse(v.ToString(CultureInfo.InvariantCulture)),
            double v => ExactOrThrow(v),
            float v => ExactOrThrow(v),
            Half v => ExactOrThrow((double)v),
            Rational v => v,
            _ => null,
        };
        if (exact is null && value is Scalar s)
        {
            result = s;
            return true;
        }
        result = exact is { } r ? Constant(r) : Zero;
        return exact is not null;
    }

    private static Rational ExactOrThrow(double value) =>
        double.IsFinite(value) ? Rational.FromDouble(value) : throw new OverflowException($"{value} has no exact symbolic value.");

    private static bool TryConvertTo<TOther>(Scalar value, out TOther result)
    {
        result = default!;
        if (!value.TryGetConstant(out var c)) return false;
        object? converted = default(TOther) switch
        {
            double => c.ToDouble(),
            float => (float)c.ToDouble(),
            decimal => (decimal)c.ToDouble(),
            int when c.IsInteger => (int)c.Numerator,
            long when c.IsInteger => (long)c.Numerator,
            _ when typeof(TOther) == typeof(BigInteger) && c.IsInteger => c.Numerator,
            _ when typeof(TOther) == typeof(Rational) => c,
            _ => null,
        };
        if (converted is null) return false;
        result = (TOther)converted;
        return true;
    }

    // ---- parsing and formatting -----------------------------------------------------------

    public static Scalar Parse(string s) => ScalarParser.Parse(s);

    public static bool TryParse(string? s, out Scalar result)
    {
        result = Zero;
        if (s is null) return false;
        try
        {
            result = ScalarParser.Parse(s);
            return true;
        }
        catch (ScalarSyntaxException)
        {
            return false;
        }
    }

    public static Scalar Parse(string s, IFormatProvider? provider) => Parse(s);
    public static Scalar Parse(string s, NumberStyles style, IFormatProvider? provider) => Parse(s);
    public static Scalar Parse(ReadOnlySpan<char> s, IFormatProvider? provider) => Parse(s.ToString());
    public static Scalar Parse(ReadOnlySpan<char> s, NumberStyles style, IFormatProvider? provider) => Parse(s.ToString());

    public static bool TryParse(string? s, IFormatProvider? provider, out Scalar result) => TryParse(s, out result);
    public static bool TryParse(string? s, NumberStyles style, IFormatProvider? provider, out Scalar result) => TryParse(s, out result);
    public static bool TryParse(ReadOnlySpan<char> s, IFormatProvider? provider, out Scalar result) => TryParse(s.ToString(), out result);
    public static bool TryParse(ReadOnlySpan<char> s, NumberStyles style, IFormatProvider? provider, out Scalar result) => TryParse(s.ToString(), out result);

    /// <summary>The format and provider are ignored: the canonical text is culture-invariant.</summary>
    public string ToString(string? format, IFormatProvider? formatProvider) => ToString();

    [ThreadStatic]
    private static (Scalar Scalar, string Text)? _lastFormatted;

    public bool TryFormat(Span<char> destination, out int charsWritten, ReadOnlySpan<char> format, IFormatProvider? provider)
    {
        // String interpolation retries with a doubled buffer until the text fits; keeping the last
        // text makes those retries copies instead of printing the whole expression again each time.
        var last = _lastFormatted;
        string text;
        if (last is not null && ReferenceEquals(last.Value.Scalar, this)) text = last.Value.Text;
        else
        {
            text = ToString();
            _lastFormatted = (this, text);
        }
        if (text.Length > destination.Length)
        {
            charsWritten = 0;
            return false;
        }
        text.CopyTo(destination);
        charsWritten = text.Length;
        return true;
    }
}
