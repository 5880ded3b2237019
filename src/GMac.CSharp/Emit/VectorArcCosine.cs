namespace GMac.CSharp.Emit;

/// <summary>
/// acos on all lanes of a fixed-width double vector at once, for .NET has no vector form of it and
/// computing it lane by lane with <c>Math.Acos</c> was measured slower than the plain scalar loop.
/// The method is the classic one of fdlibm's <c>__ieee754_acos</c> (within one unit in the last
/// place): with one rational approximation R(z) of (asin √z − √z)/√z on [0, 1/4],
/// <list type="bullet">
/// <item>|x| ≤ ½: acos x = π/2 − (x + x·R(x²)), π/2 in two parts so the sum stays exact;</item>
/// <item>x &lt; −½: acos x = π − 2(s + s·R(z)), z = (1 + x)/2, s = √z;</item>
/// <item>x &gt; ½: acos x = 2(s + s·R(z)), z = (1 − x)/2, with s split into a high part whose square is
/// exact plus a correction, so the rounding of √z does not reach the result.</item>
/// </list>
/// Every lane computes z for its own branch, R once, and the three results are blended; NaN and
/// |x| &gt; 1 give NaN through the square root, as <c>Math.Acos</c> does.
/// </summary>
internal static class VectorArcCosine
{
    // R(z) = z·P(z)/Q(z), the coefficients of fdlibm's e_acos.c.
    private static readonly double[] P = [1.66666666666666657415e-01, -3.25565818622400915405e-01, 2.01212532134862925881e-01,
        -4.00555345006794114027e-02, 7.91534994289814532176e-04, 3.47933107596021167570e-05];
    private static readonly double[] Q = [1.0, -2.40339491173441421878e+00, 2.02094576023350569471e+00,
        -6.88283971605453293030e-01, 7.70381505559019352791e-02];

    private const double HalfPiHigh = 1.57079632679489655800e+00;
    private const double HalfPiLow = 6.12323399573676603587e-17;
    private const double Pi = 3.14159265358979311600e+00;

    /// <summary>
    /// The statements that compute acos of the vector named <paramref name="x"/>, added to
    /// <paramref name="statements"/>; returns the name of the result.
    /// </summary>
    /// <param name="family">Vector128, Vector256 or Vector512 (double lanes).</param>
    /// <param name="constant">The name of a broadcast constant.</param>
    /// <param name="freshName">A new local name.</param>
    public static string Emit(string family, string x, Func<double, string> constant, Func<string> freshName, List<string> statements)
    {
        string Let(string value)
        {
            var name = freshName();
            statements.Add($"var {name} = {value};");
            return name;
        }
        string Horner(double[] coefficients, string z)
        {
            var text = constant(coefficients[^1]);
            for (var i = coefficients.Length - 2; i >= 0; i--)
                text = $"{constant(coefficients[i])} + {z} * {(i == coefficients.Length - 2 ? text : $"({text})")}";
            return text;
        }

        var half = constant(0.5);
        var magnitude = Let($"{family}.Abs({x})");
        var small = Let($"{family}.LessThanOrEqual({magnitude}, {half})");
        var z = Let($"{family}.ConditionalSelect({small}, {x} * {x}, ({constant(1)} - {magnitude}) * {half})");
        var r = Let($"{z} * ({Horner(P, z)}) / ({Horner(Q, z)})");
        var nearZero = Let($"{constant(HalfPiHigh)} - ({x} - ({constant(HalfPiLow)} - {x} * {r}))");
        var s = Let($"{family}.Sqrt({z})");
        var nearMinusOne = Let($"{constant(Pi)} - {constant(2)} * ({s} + ({r} * {s} - {constant(HalfPiLow)}))");
        // The high 32 bits of s: its square is exact, so z − high² is the exact remainder.
        var high = Let($"{family}.AsDouble({family}.AsUInt64({s}) & {family}.Create(0xFFFFFFFF00000000UL))");
        var sum = Let($"{s} + {high}");
        // At x = 1 the remainder is 0/0; the answer there is 0.
        var correction = Let($"{family}.ConditionalSelect({family}.Equals({sum}, {family}<double>.Zero), {family}<double>.Zero, ({z} - {high} * {high}) / {sum})");
        var nearOne = Let($"{constant(2)} * ({high} + ({r} * {s} + {correction}))");
        return Let($"{family}.ConditionalSelect({small}, {nearZero}, {family}.ConditionalSelect({family}.LessThan({x}, {family}<double>.Zero), {nearMinusOne}, {nearOne}))");
    }
}
