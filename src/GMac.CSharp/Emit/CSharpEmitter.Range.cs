using System.Globalization;
using System.Numerics;
using GMac.Core.CodeGeneration;

namespace GMac.CSharp.Emit;

public static partial class CSharpEmitter
{
    /// <summary>
    /// A message naming the first constant of the block that has no finite value in the scalar type
    /// (10^39 as a float, 10^400 as a double), or null. Such a constant would print as <c>Infinity</c>,
    /// which is not C#: callers report it as a diagnostic instead of emitting.
    /// </summary>
    public static string? ConstantOutOfRange(CodeBlock block, string scalarType)
    {
        var single = IsSingle(scalarType);
        foreach (var statement in block.Statements)
        foreach (var expression in statement.Expressions)
        foreach (var node in new ExprWalk(expression))
        {
            if (node is not ConstantExpr c || (single ? float.IsFinite(SingleLiteral.ValueOf(c)) : double.IsFinite(c.Value))) continue;
            var largest = single ? float.MaxValue.ToString("R", CultureInfo.InvariantCulture) : double.MaxValue.ToString("R", CultureInfo.InvariantCulture);
            return $"the constant {Magnitude(c)} is outside the range of {scalarType} (largest magnitude {largest})";
        }
        return null;
    }

    /// <summary>The constant in scientific notation, from its exact value where a double cannot hold it.</summary>
    private static string Magnitude(ConstantExpr c)
    {
        if (double.IsFinite(c.Value)) return c.Value.ToString("R", CultureInfo.InvariantCulture);
        if (c.Exact is not { IsZero: false } r) return double.IsNaN(c.Value) ? "NaN" : c.Value > 0 ? "infinity" : "-infinity";
        var log10 = BigInteger.Log10(BigInteger.Abs(r.Numerator)) - BigInteger.Log10(r.Denominator);
        var exponent = Math.Floor(log10);
        var mantissa = Math.Pow(10, log10 - exponent);
        return string.Create(CultureInfo.InvariantCulture, $"{(r.Sign < 0 ? "-" : "")}{mantissa:0.###}E+{exponent}");
    }
}
