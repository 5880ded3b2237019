using GMac.Core.CodeGeneration;
using GMac.CSharp.Emit;
using GMac.CSharp.Verification;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.CSharp.Tests.Emit;

/// <summary>
/// acos on double vectors is computed on all lanes at once; every lane is within one unit in the last
/// place of Math.Acos, on random arguments and where approximations break: near ±1, at the branch
/// points ±½, near 0, and outside [−1, 1].
/// </summary>
public sealed class CSharpVectorEmitter_ArcCosine
{
    private static readonly string[] DoubleTypes = ["Vector128<double>", "Vector256<double>", "Vector512<double>"];

    private static IEnumerable<double> Arguments()
    {
        double[] special = [0.0, -0.0, 1.0, -1.0, 0.5, -0.5, double.Epsilon, -double.Epsilon, 1e-300, 1e-17, -1e-17,
            Math.BitDecrement(0.5), Math.BitIncrement(0.5), Math.BitDecrement(-0.5), Math.BitIncrement(-0.5),
            Math.BitDecrement(1.0), Math.BitIncrement(-1.0), Math.BitIncrement(1.0), Math.BitDecrement(-1.0), 2.0, -7.5,
            double.NaN, double.PositiveInfinity, double.NegativeInfinity];
        var random = new Random(2026);
        var near = Enumerable.Range(1, 52).SelectMany(k => new[] { 1 - Math.ScaleB(1, -k), -1 + Math.ScaleB(1, -k), 0.5 + Math.ScaleB(1, -k - 1), Math.ScaleB(1, -k) });
        var uniform = Enumerable.Range(0, 4000).Select(_ => random.NextDouble() * 2 - 1);
        return special.Concat(near).Concat(uniform);
    }

    [Fact]
    public void Every_lane_is_within_one_unit_in_the_last_place_of_the_scalar_function()
    {
        var block = new CodeBlock([new AssignmentStatement("o0", Call("acos", Variable("a")), true)],
            new Dictionary<string, string> { ["a"] = "a" }, new Dictionary<string, string> { ["o0"] = "o0Target" });
        var remapped = KernelCompiler.Remap(block, ["a"]);
        var kernels = KernelCompiler.Compile(DoubleTypes.Select(_ => remapped).ToList(), DoubleTypes);
        var arguments = Arguments().ToArray();
        for (var k = 0; k < DoubleTypes.Length; k++)
        {
            var (kernel, error) = kernels[k];
            Assert.True(kernel is not null, $"{DoubleTypes[k]}: {error}");
            var lanes = kernel!.Lanes;
            for (var start = 0; start < arguments.Length; start += lanes)
            {
                var input = Enumerable.Range(start, lanes).Select(i => arguments[i % arguments.Length]).ToArray();
                var output = new double[lanes];
                kernel.Run(input, output);
                for (var l = 0; l < lanes; l++)
                {
                    var expected = Math.Acos(input[l]);
                    Assert.True(WithinOneUnit(output[l], expected), $"{DoubleTypes[k]}: acos({input[l]:R}) = {output[l]:R}, Math.Acos gives {expected:R}");
                }
            }
        }
    }

    [Fact]
    public void The_vector_code_calls_no_scalar_function()
    {
        var block = new CodeBlock([new AssignmentStatement("o0", Call("acos", Sum(Variable("a"), Variable("b"))), true)],
            new Dictionary<string, string> { ["a"] = "a", ["b"] = "b" }, new Dictionary<string, string> { ["o0"] = "x" });
        var code = CSharpEmitter.Emit(block, new CSharpEmitOptions { ScalarType = "Vector256<double>" });
        Assert.DoesNotContain("Math.", code);
        Assert.DoesNotContain("GetElement", code);
        Assert.Contains("Vector256.Sqrt(", code);
        var single = CSharpEmitter.Emit(block, new CSharpEmitOptions { ScalarType = "Vector256<float>" });
        Assert.Contains("MathF.Acos(", single); // float lanes keep MathF.Acos lane by lane
    }

    private static bool WithinOneUnit(double actual, double expected) =>
        double.IsNaN(expected) ? double.IsNaN(actual) : actual == expected || Math.BitIncrement(actual) == expected || Math.BitDecrement(actual) == expected;
}
