using System.Text.RegularExpressions;
using GMac.Core.CodeGeneration;
using GMac.CSharp.Emit;
using GMac.CSharp.Verification;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.CSharp.Tests.Emit;

/// <summary>
/// Vector code: constants broadcast once at the top, vector forms where .NET has them, and functions
/// without one (tan, atan2, pow, sinh, cosh, acos on float lanes) computed lane by lane with Math's, equal to it in every lane.
/// </summary>
public sealed partial class CSharpVectorEmitter_Lanes
{
    private static readonly Dictionary<string, string> Inputs = new() { ["a"] = "a", ["b"] = "b" };

    /// <summary>Outputs o0… of the given values, each to a target of its own.</summary>
    private static CodeBlock Block(params Expr[] outputs) =>
        new(outputs.Select((e, i) => (CodeStatement)new AssignmentStatement($"o{i}", e, true)), Inputs,
            outputs.Select((_, i) => $"o{i}").ToDictionary(o => o, o => o + "Target", StringComparer.Ordinal));

    private static Expr A => Variable("a");
    private static Expr B => Variable("b");

    [Fact]
    public void A_constant_used_many_times_is_broadcast_once_before_every_other_statement()
    {
        var block = new CodeBlock(
        [
            new AssignmentStatement("t", Product(Constant(2), A), false),
            new AssignmentStatement("o0", Sum(Variable("t"), Product(Constant(2), B)), true),
            new AssignmentStatement("o1", Sum(Product(Constant(2), Variable("t")), Constant(-0.5)), true),
        ], Inputs, new Dictionary<string, string> { ["o0"] = "x", ["o1"] = "y" });
        var code = CSharpEmitter.Emit(block, new CSharpEmitOptions { ScalarType = "Vector256<double>" });
        var lines = code.Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.Single(Regex.Matches(code, @"Vector256\.Create\(2\.0\)"));
        Assert.Equal("var tmpC0 = Vector256.Create(2.0);", lines[0]);
        Assert.Equal("var tmp0 = tmpC0 * a;", lines[2]);
        Assert.Contains("x = tmp0 + tmpC0 * b;", lines);
        Assert.DoesNotMatch(@"[^C]\d\.\d", string.Join("\n", lines.Skip(2)));
    }

    [Fact]
    public void Constant_names_avoid_names_taken_where_the_code_goes()
    {
        var code = CSharpEmitter.Emit(Block(Product(Constant(3), A)), new CSharpEmitOptions { ScalarType = "Vector128<float>", IsNameTaken = n => n == "tmpC0" });
        Assert.Equal("var tmpC1 = Vector128.Create(3.0f);\no0Target = tmpC1 * a;\n", code);
    }

    [Theory]
    [InlineData("Vector256<double>", "Vector256.Sqrt(a)", "Vector256.Sin(a)")]
    [InlineData("Vector512<float>", "Vector512.Sqrt(a)", "Vector512.Sin(a)")]
    [InlineData("Vector<double>", "Vector.SquareRoot(a)", "Vector.Sin(a)")]
    public void Sqrt_sin_cos_exp_log_and_abs_are_vector_functions(string type, string sqrt, string sin)
    {
        var code = CSharpEmitter.Emit(Block(Call("sqrt", A), Call("sin", A), Call("exp", B), Call("log", B), Call("abs", B), Negate(Quotient(A, B))),
            new CSharpEmitOptions { ScalarType = type });
        Assert.Contains(sqrt, code);
        Assert.Contains(sin, code);
        Assert.Contains("o5Target = -(a / b);", code);
        Assert.DoesNotContain("Math", code);
        Assert.DoesNotContain("GetElement", code);
    }

    [Fact]
    public void A_function_without_a_vector_form_is_computed_lane_by_lane_from_arguments_evaluated_once()
    {
        var code = CSharpEmitter.Emit(Block(Call("atan2", Sum(A, B), A)), new CSharpEmitOptions { ScalarType = "Vector128<double>" });
        Assert.Equal(
            "var tmpL0 = a + b;\n" +
            "var tmpL1 = Vector128.Create(Math.Atan2(Vector128.GetElement(tmpL0, 0), Vector128.GetElement(a, 0)), Math.Atan2(Vector128.GetElement(tmpL0, 1), Vector128.GetElement(a, 1)));\n" +
            "o0Target = tmpL1;\n", code);
    }

    /// <summary>Every vector type, each with per-lane and vector functions, against Math (MathF) lane by lane.</summary>
    [Fact]
    public void Per_lane_functions_equal_the_scalar_functions_in_every_lane_of_every_vector_type()
    {
        var block = Block(Call("acos", A), Call("tan", B), Call("atan2", A, B), Call("pow", Call("abs", B), A), Power(Sum(A, B), 3),
            Call("atan2", Call("acos", A), Constant(0.5)), Call("sqrt", A), Quotient(Constant(1), B), Call("sinh", A), Call("cosh", B));
        var remapped = KernelCompiler.Remap(block, ["a", "b"]);
        var types = CSharpVectorEmitter.Instance.ScalarTypes;
        var kernels = KernelCompiler.Compile(types.Select(_ => remapped).ToList(), types);
        var random = new Random(11);
        for (var k = 0; k < types.Count; k++)
        {
            var (kernel, error) = kernels[k];
            Assert.True(kernel is not null, $"{types[k]}: {error}");
            var lanes = kernel!.Lanes;
            Assert.Equal(types[k].StartsWith("Vector<", StringComparison.Ordinal) ? System.Numerics.Vector<byte>.Count : int.Parse(types[k][6..9], System.Globalization.CultureInfo.InvariantCulture) / 8,
                lanes * (kernel.IsSingle ? 4 : 8));
            // Lane 0 has a out of acos's domain and b = 0: NaN and infinity stay in their lanes.
            var input = Enumerable.Range(0, 2 * lanes).Select(i => i % lanes == 0 ? (i == 0 ? 1.5 : 0.0) : random.NextDouble() * 1.8 - 0.9).ToArray();
            if (kernel.IsSingle) input = input.Select(x => (double)(float)x).ToArray();
            var output = new double[10 * lanes];
            kernel.Run(input, output);
            for (var l = 0; l < lanes; l++)
            {
                var (a, b) = (input[l], input[lanes + l]);
                double[] expected = kernel.IsSingle
                    ? [MathF.Acos((float)a), MathF.Tan((float)b), MathF.Atan2((float)a, (float)b), MathF.Pow(MathF.Abs((float)b), (float)a), MathF.Pow((float)a + (float)b, 3f),
                        MathF.Atan2(MathF.Acos((float)a), 0.5f), MathF.Sqrt((float)a), 1f / (float)b, MathF.Sinh((float)a), MathF.Cosh((float)b)]
                    : [Math.Acos(a), Math.Tan(b), Math.Atan2(a, b), Math.Pow(Math.Abs(b), a), Math.Pow(a + b, 3), Math.Atan2(Math.Acos(a), 0.5), Math.Sqrt(a), 1 / b, Math.Sinh(a), Math.Cosh(b)];
                for (var j = 0; j < expected.Length; j++)
                {
                    // acos of double vectors is vectorized (CSharpVectorEmitter_ArcCosine): within a unit in the last place.
                    var vectorAcos = j is 0 or 5 && !kernel.IsSingle && !types[k].StartsWith("Vector<", StringComparison.Ordinal);
                    var actual = output[j * lanes + l];
                    Assert.True(vectorAcos ? Math.Abs(actual - expected[j]) <= 2 * Math.Abs(Math.BitIncrement(expected[j]) - expected[j]) || expected[j].Equals(actual)
                        : expected[j].Equals(actual), $"{types[k]} lane {l} output {j}: {actual:R}, Math gives {expected[j]:R}");
                }
            }
        }
    }
}
