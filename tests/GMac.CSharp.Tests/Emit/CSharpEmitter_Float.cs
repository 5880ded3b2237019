using System.Numerics;
using GMac.Core.CodeGeneration;
using GMac.CSharp.Emit;
using GMac.Core.Numerics;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.CSharp.Tests.Emit;

/// <summary>Float code: <c>float</c> temporaries, <c>MathF</c> calls, <c>f</c> literals rounded once from exact values.</summary>
public sealed class CSharpEmitter_Float
{
    private static CodeBlock Block(IReadOnlyDictionary<string, string> inputs, params CodeStatement[] statements) =>
        new(statements, inputs, statements.OfType<AssignmentStatement>().Where(s => s.IsOutput).ToDictionary(s => s.Target, s => s.Target + "Target", StringComparer.Ordinal));

    [Fact]
    public void Float_code_declares_floats_calls_mathf_and_writes_suffixed_literals()
    {
        var inputs = new Dictionary<string, string> { ["a"] = "a", ["c"] = "angle" };
        var block = Block(inputs,
            new AssignmentStatement("x", Sum(Variable("a"), Constant(new Rational(1, 3))), false),
            new AssignmentStatement("o", Product(Variable("x"), Call("cos", Variable("c")), Constant(2)), true),
            new AssignmentStatement("p", Sum(Variable("x"), Constant(new Rational(-1, 10))), true));
        var code = CSharpEmitter.Emit(block, new CSharpEmitOptions { ScalarType = "float" });
        Assert.Equal("float tmp0 = a + 0.33333334f;\noTarget = 2.0f * tmp0 * MathF.Cos(angle);\npTarget = tmp0 - 0.1f;\n", code);
    }

    [Fact]
    public void Declared_outputs_get_the_scalar_type_once()
    {
        var inputs = new Dictionary<string, string> { ["a"] = "a" };
        var block = Block(inputs, new AssignmentStatement("o", Product(Variable("a"), Variable("a")), true));
        Assert.Equal("float oTarget = a * a;\n", CSharpEmitter.Emit(block, new CSharpEmitOptions { ScalarType = "float", DeclareOutputs = true }));
        Assert.Equal("oTarget = a * a;\n", CSharpEmitter.Emit(block, new CSharpEmitOptions { ScalarType = "float" }));
    }

    [Fact]
    public void An_unknown_scalar_type_is_refused()
    {
        var block = Block(new Dictionary<string, string> { ["a"] = "a" }, new AssignmentStatement("o", Variable("a"), true));
        Assert.Throws<InvalidOperationException>(() => CSharpEmitter.Emit(block, new CSharpEmitOptions { ScalarType = "decimal" }));
    }

    [Fact]
    public void A_rational_just_above_a_tie_rounds_up_where_rounding_through_double_goes_down()
    {
        // 1 + 2^-24 + 2^-60: the double nearest it is 1 + 2^-24, a tie between floats that goes to 1;
        // the value itself lies above the tie, so the nearest float is 1 + 2^-23.
        var value = new Rational((BigInteger.One << 60) + (BigInteger.One << 36) + 1, BigInteger.One << 60);
        Assert.Equal(1f, (float)value.ToDouble());
        Assert.Equal(1f + MathF.Pow(2, -23), SingleLiteral.Round(value));
        Assert.Equal(-(1f + MathF.Pow(2, -23)), SingleLiteral.Round(-value));
    }

    [Fact]
    public void Rounded_rationals_are_the_nearest_float()
    {
        var random = new Random(11);
        for (var i = 0; i < 2000; i++)
        {
            var value = new Rational(random.NextInt64(-1_000_000_000_000, 1_000_000_000_000), random.NextInt64(1, 1_000_000_000));
            var rounded = SingleLiteral.Round(value);
            var error = (Rational.FromDouble(rounded) - value).Abs();
            // Neither neighbouring float is closer (exact comparisons in rationals).
            Assert.True(error <= (Rational.FromDouble(MathF.BitIncrement(rounded)) - value).Abs(), $"{value}");
            Assert.True(error <= (Rational.FromDouble(MathF.BitDecrement(rounded)) - value).Abs(), $"{value}");
        }
    }

    [Fact]
    public void Float_literals_read_back_to_the_same_float_and_are_never_integers()
    {
        Assert.Equal("2.0f", SingleLiteral.Text(2f));
        Assert.Equal("0.1f", SingleLiteral.Text(0.1f));
        Assert.Equal("1E-20f", SingleLiteral.Text(1e-20f));
        Assert.Equal("-0.5f", SingleLiteral.Of(ConstantExpr.From(new Rational(-1, 2))));
    }
}
