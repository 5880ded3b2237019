using System.Globalization;
using GMac.CSharp.Tests.Support;
using GMac.CSharp.Verification;

namespace GMac.CSharp.Tests.Verification;

/// <summary>
/// Every library macro, generated with its default bindings as Vector256&lt;double&gt; and
/// Vector128&lt;float&gt;, gives in each lane what the scalar double (float) code gives for that
/// lane's inputs: every lane a different random sample, NaN exactly where the scalar code has NaN.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class VectorKernels_MatchScalarKernels
{
    private const int Rounds = 3;

    private static readonly Lazy<IReadOnlyList<(string Macro, string Scalar, string Vector, CompiledKernel ScalarKernel, CompiledKernel VectorKernel)>> Kernels = new(Compile);

    /// <summary>All macros and all four scalar types in one Roslyn compilation, as gmac verify compiles a run.</summary>
    private static IReadOnlyList<(string, string, string, CompiledKernel, CompiledKernel)> Compile()
    {
        var context = SharedDsl.Context;
        var pairs = new[] { ("double", "Vector256<double>"), ("float", "Vector128<float>") };
        var blocks = new List<KernelBlock>();
        var types = new List<string>();
        var macros = new List<(string Macro, string Scalar, string Vector)>();
        foreach (var macro in context.Project.Model.Macros.Keys.Order(StringComparer.Ordinal))
        {
            var outcome = context.Generator.Generate(macro, context.Generator.DefaultBindings(macro), 1);
            Assert.True(outcome.Succeeded, $"{macro}: {string.Join("\n", outcome.Errors)}");
            var remapped = KernelCompiler.Remap(outcome.Result!.Block, outcome.Plan!.InputTexts.Keys);
            foreach (var (scalar, vector) in pairs)
            {
                // A constant beyond the float range is a diagnostic, not code, in either form.
                if (GMac.CSharp.Emit.CSharpEmitter.ConstantOutOfRange(outcome.Result.Block, scalar) is not null) continue;
                blocks.Add(remapped);
                blocks.Add(remapped);
                types.Add(scalar);
                types.Add(vector);
                macros.Add((macro, scalar, vector));
            }
        }
        var kernels = KernelCompiler.Compile(blocks, types);
        return macros.Select((m, k) =>
        {
            var (scalarKernel, scalarError) = kernels[2 * k];
            var (vectorKernel, vectorError) = kernels[2 * k + 1];
            Assert.True(scalarKernel is not null, $"{m.Macro} as {m.Scalar}: {scalarError}");
            Assert.True(vectorKernel is not null, $"{m.Macro} as {m.Vector}: {vectorError}");
            return (m.Macro, m.Scalar, m.Vector, scalarKernel!, vectorKernel!);
        }).ToList();
    }

    [Fact]
    public void Every_library_macro_compiles_in_both_vector_types()
    {
        var kernels = Kernels.Value;
        var macros = SharedDsl.Context.Project.Model.Macros.Count;
        Assert.True(macros > 50, $"only {macros} library macros");
        Assert.Equal(macros, kernels.Count(k => k.Vector == "Vector256<double>"));
        Assert.All(kernels, k => Assert.Equal(4, k.VectorKernel.Lanes)); // 256 bits of double, 128 of float
    }

    [Fact]
    public void Every_lane_of_every_library_macro_agrees_with_the_scalar_code_on_its_own_inputs()
    {
        var random = new Random(26);
        var failures = new List<string>();
        var lanesCompared = 0;
        foreach (var (macro, scalar, vector, scalarKernel, vectorKernel) in Kernels.Value)
        {
            var single = vectorKernel.IsSingle;
            var tolerance = single ? 1e-4 : 1e-12;
            var lanes = vectorKernel.Lanes;
            var (inputs, outputs) = (scalarKernel.Inputs.Count, scalarKernel.Outputs.Count);
            for (var round = 0; round < Rounds; round++)
            {
                var input = new double[inputs * lanes];
                for (var i = 0; i < input.Length; i++) input[i] = random.NextDouble() * 3 - 1.5;
                if (single) for (var i = 0; i < input.Length; i++) input[i] = (float)input[i];
                var output = new double[outputs * lanes];
                Array.Fill(output, double.NaN);
                vectorKernel.Run(input, output);
                for (var l = 0; l < lanes; l++)
                {
                    var laneInput = Enumerable.Range(0, inputs).Select(i => input[i * lanes + l]).ToArray();
                    var expected = new double[outputs];
                    Array.Fill(expected, double.NaN);
                    scalarKernel.Run(laneInput, expected);
                    lanesCompared++;
                    for (var j = 0; j < outputs; j++)
                    {
                        var actual = output[j * lanes + l];
                        var error = Math.Abs(actual - expected[j]) / Math.Max(1.0, Math.Max(Math.Abs(expected[j]), Math.Abs(actual)));
                        var agrees = double.IsNaN(expected[j]) ? double.IsNaN(actual)
                            : double.IsInfinity(expected[j]) ? actual == expected[j]
                            : error <= tolerance;
                        if (!agrees)
                            failures.Add(string.Create(CultureInfo.InvariantCulture,
                                $"{macro} {vector} lane {l} output '{scalarKernel.Outputs[j]}': {actual:R}, scalar {scalar} code {expected[j]:R}"));
                    }
                }
            }
        }
        Assert.True(failures.Count == 0, string.Join("\n", failures.Take(20)));
        Assert.True(lanesCompared > 1000, $"only {lanesCompared} lanes compared");
    }
}
