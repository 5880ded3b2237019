using System.Globalization;
using System.Numerics;
using GMac.Core.Numerics;
using GMac.Core.CodeGeneration;

namespace GMac.CSharp.Emit;

/// <summary>
/// <c>float</c> literals for emitted code. An exact constant is rounded once, from its rational
/// value straight to the nearest float, so a constant such as 1/3 is the float nearest 1/3 and
/// not the float nearest the double nearest 1/3. A constant known only as a double (π, a folded
/// square root) is within a double rounding of its value, which narrowing adds to the float rounding.
/// </summary>
public static class SingleLiteral
{
    private const float SmallestNormal = 1.17549435E-38f;

    /// <summary>The C# text of the constant as a float: shortest round-trip digits and an <c>f</c> suffix.</summary>
    public static string Of(ConstantExpr constant) => Text(ValueOf(constant));

    /// <summary>The float the constant prints as: infinite when it is beyond the float range.</summary>
    public static float ValueOf(ConstantExpr constant) => constant.Exact is { } r ? Round(r) : (float)constant.Value;

    /// <summary>The C# text of <paramref name="value"/> with an <c>f</c> suffix, never an integer literal.</summary>
    public static string Text(float value)
    {
        var text = value.ToString("R", CultureInfo.InvariantCulture);
        if (!text.Contains('.') && !text.Contains('E') && !text.Contains("Infinity") && !text.Contains("NaN")) text += ".0";
        return text + "f";
    }

    /// <summary>The float nearest <paramref name="value"/> (ties to even), rounded once.</summary>
    public static float Round(Rational value)
    {
        if (value.IsZero) return 0f;
        var numerator = BigInteger.Abs(value.Numerator);
        var denominator = value.Denominator;
        // Scale so the quotient has 26 or 27 bits: more than a float's 24, and exact in a double.
        var shift = 26 - (int)(numerator.GetBitLength() - denominator.GetBitLength());
        if (Math.Abs(shift) > 900) return (float)value.ToDouble(); // far outside the float range anyway
        var quotient = BigInteger.DivRem(shift >= 0 ? numerator << shift : numerator, shift >= 0 ? denominator : denominator << -shift, out var remainder);
        // A sticky bit below the rounding position keeps a value just above a tie from rounding as the tie.
        quotient = quotient * 2 + (remainder.IsZero ? 0 : 1);
        var exact = Math.ScaleB((double)quotient, -(shift + 1)); // at most 28 bits: exact, barring double underflow
        var rounded = (float)exact;
        // Subnormal floats round at a coarser bit than the one the sticky bit guards; the double path is as good there.
        if (rounded < SmallestNormal || float.IsInfinity(rounded)) rounded = (float)value.ToDouble();
        return value.Sign < 0 ? -rounded : rounded;
    }
}
