using System.Globalization;
using System.Text.RegularExpressions;
using GMac.CSharp.Emit;
using GMac.CSharp.Tests.Support;
using GMac.CSharp.Verification;

namespace GMac.CSharp.Tests.Emit;

/// <summary>
/// With <see cref="CSharpEmitOptions.FusedMultiplyAdd"/>, library macros compiled as double, float and
/// Vector256&lt;double&gt; code compute what the unfused code computes (within the rounding the fusion
/// saves) on random inputs, and their code has fused calls in place of separate products and sums.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed partial class CSharpEmitter_FusedMultiplyAdd
{
    private static readonly string[] Macros = ["NormalToVectors", "ApplyUnitRotor3D", "SphereCentreAndRadius", "SkewLinesClosestPoints", "GramSchmidtRejection"];
    private static readonly string[] Types = ["double", "float", "Vector256<double>"];

    private static KernelBlock Block(string macro)
    {
        var context = SharedDsl.Context;
        var outcome = context.Generator.Generate(macro, context.Generator.DefaultBindings(macro), 1);
        Assert.True(outcome.Succeeded, $"{macro}: {string.Join("\n", outcome.Errors)}");
        return KernelCompiler.Remap(outcome.Result!.Block, outcome.Plan!.InputTexts.Keys);
    }

    [Fact]
    public void Fused_code_agrees_with_unfused_code_on_random_inputs()
    {
        var blocks = new List<KernelBlock>();
        var types = new List<string>();
        foreach (var macro in Macros)
        {
            var block = Block(macro);
            foreach (var type in Types)
            {
                blocks.Add(block);
                blocks.Add(block with { FusedMultiplyAdd = true });
                types.Add(type);
                types.Add(type);
            }
        }
        var kernels = KernelCompiler.Compile(blocks, types);
        var random = new Random(26);
        var failures = new List<string>();
        var compared = 0;
        for (var k = 0; k < kernels.Count; k += 2)
        {
            var (plain, plainError) = kernels[k];
            var (fused, fusedError) = kernels[k + 1];
            Assert.True(plain is not null, plainError);
            Assert.True(fused is not null, fusedError);
            var single = plain!.IsSingle;
            var tolerance = single ? 1e-4 : 1e-11;
            for (var round = 0; round < 20; round++)
            {
                var input = new double[plain.Inputs.Count * plain.Lanes];
                for (var i = 0; i < input.Length; i++) input[i] = random.NextDouble() * 3 - 1.5;
                if (single) for (var i = 0; i < input.Length; i++) input[i] = (float)input[i];
                var expected = new double[plain.Outputs.Count * plain.Lanes];
                var actual = new double[expected.Length];
                plain.Run(input, expected);
                fused!.Run(input, actual);
                for (var j = 0; j < expected.Length; j++)
                {
                    compared++;
                    var error = Math.Abs(actual[j] - expected[j]) / Math.Max(1.0, Math.Max(Math.Abs(expected[j]), Math.Abs(actual[j])));
                    if (!(error <= tolerance) && !(double.IsNaN(expected[j]) && double.IsNaN(actual[j])))
                        failures.Add(string.Create(CultureInfo.InvariantCulture, $"{Macros[k / 2 / Types.Length]} {types[k]} slot {j}: fused {actual[j]:R}, unfused {expected[j]:R}"));
                }
            }
        }
        Assert.True(failures.Count == 0, string.Join("\n", failures.Take(20)));
        Assert.True(compared > 1000, $"only {compared} values compared");
    }

    [Theory]
    [InlineData("double", "Math.FusedMultiplyAdd(")]
    [InlineData("float", "MathF.FusedMultiplyAdd(")]
    [InlineData("Vector256<double>", "Vector256.FusedMultiplyAdd(")]
    [InlineData("Vector<float>", "Vector.FusedMultiplyAdd(")]
    public void Fused_code_calls_fma_in_place_of_separate_products_and_sums(string type, string call)
    {
        foreach (var macro in Macros)
        {
            var block = Block(macro).Block;
            var plain = CSharpEmitter.Emit(block, new CSharpEmitOptions { ScalarType = type });
            var fused = CSharpEmitter.Emit(block, new CSharpEmitOptions { ScalarType = type, FusedMultiplyAdd = true });
            Assert.DoesNotContain("FusedMultiplyAdd", plain);
            var calls = Regex.Matches(fused, Regex.Escape(call)).Count;
            Assert.True(calls > 0, $"{macro} as {type}:\n{fused}");
            // Each call takes the place of one product and one sum (a binary minus counts as a sum).
            Assert.Equal(Operators(plain, '*') - calls, Operators(fused, '*'));
            Assert.Equal(Operators(plain, '+') + Operators(plain, '-') - calls, Operators(fused, '+') + Operators(fused, '-'));
        }
    }

    /// <summary>Binary operators <paramref name="op"/> in the code: with a space on each side, as the printer writes them.</summary>
    private static int Operators(string code, char op) => Regex.Matches(code, $@" {Regex.Escape(op.ToString())} ").Count;
}
