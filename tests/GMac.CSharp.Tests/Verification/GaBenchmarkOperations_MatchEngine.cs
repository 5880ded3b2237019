using GMac.CSharp.BindingPoints;
using GMac.CSharp.Tests.Support;
using GMac.CSharp.Verification;
using GMac.Dsl;
using GMac.Dsl.Generation;

namespace GMac.CSharp.Tests.Verification;

/// <summary>
/// The ten unary and twelve binary operations of ga-benchmark, written in GMacDSL in each of its model
/// families (Euclidean 2D–5D, homogeneous 2D–4D, conformal 2D/3D, Minkowski 2D/3D), generated,
/// compiled in one batch and compared with the numeric engine on random multivectors. The general
/// inverse is also held to A A⁻¹ = 1 in the generated code itself.
/// </summary>
public sealed class GaBenchmarkOperations_MatchEngine : IClassFixture<GaBenchmarkOperations_MatchEngine.Kernels>
{
    /// <summary>The library frames of the families: pga is the homogeneous 3D model, cga5d the conformal 3D one.</summary>
    public static readonly string[] Frames = ["e2d", "e3d", "e4d", "e5d", "h2d", "pga", "h4d", "cga4d", "cga5d", "m2d", "m3d"];

    private static readonly (string Name, string Expression)[] Operations =
    [
        // unary
        ("cc", "cliff_conj(x)"), ("du", "dual(x)"), ("gi", "grade_inv(x)"), ("inv", "general_inverse(y)"),
        ("vinv", "inverse(grade(x, 1))"), ("nrm", "x / norm(x)"), ("rev", "reverse(x)"), ("srn", "quasi_norm2(x)"),
        ("neg", "-x"), ("pos", "+x"), ("und", "undual(x)"),
        // binary
        ("add", "x + y"), ("com", "x cp y"), ("dot", "x fdp y"), ("gp", "x gp y"), ("hip", "x hip y"),
        ("igp", "x gp r_inv"), ("lcp", "x lcp y"), ("op", "x op y"), ("vee", "x vee y"), ("rcp", "x rcp y"),
        ("sp", "x sp y"), ("sub", "x - y"),
        // the identity the general inverse must meet
        ("one", "y gp r_inv"),
    ];

    /// <summary>Full multivectors up to 4D; in the 5D models two mixed-grade operands keep generation quick.</summary>
    private static readonly string[] FiveDimensional = ["e5d", "h4d", "cga5d", "m3d"];

    private static string Macro(string frame)
    {
        var operands = FiveDimensional.Contains(frame)
            ? "        x = grade(a, 1) + grade(a, 2);\n        y = grade(b, 0) + grade(b, 1) + grade(b, 4);\n"
            : "        x = a;\n        y = b;\n";
        var outputs = string.Join("; ", Operations.Select(o => $"r_{o.Name} : {frame}.Multivector"));
        var body = string.Join("\n", Operations.Select(o => $"        r_{o.Name} = {o.Expression};"));
        return $"""
            define macro GaBenchmark_{frame} as
                inputs: {"{"} a : {frame}.Multivector; b : {frame}.Multivector {"}"}
                outputs: {"{"} {outputs} {"}"}
                performs:
            {operands}{body}
            end macro

            """;
    }

    /// <summary>Every family's macro generated (in parallel) and compiled together once.</summary>
    public sealed class Kernels : IDisposable
    {
        private readonly TempFolder _folder = new();

        public Kernels()
        {
            var file = _folder.Write("gabenchmark.gmac", string.Concat(Frames.Select(Macro)));
            var context = new GenerationContext(DslProject.Load([SharedDsl.DslDirectory, file]), cacheDirectory: null);
            var outcomes = Frames.AsParallel().AsOrdered().Select(f =>
            {
                var macro = $"GaBenchmark_{f}";
                return context.Generator.Generate(macro, context.Generator.DefaultBindings(macro), 1);
            }).ToList();
            foreach (var o in outcomes) Assert.True(o.Succeeded, string.Join("\n", o.Errors));
            var compiled = KernelCompiler.Compile(outcomes.Select(o => KernelCompiler.Remap(o.Result!.Block, o.Plan!.InputTexts.Keys)).ToList());
            ByFrame = Frames.Select((f, i) => (f, compiled[i].Kernel ?? throw new InvalidOperationException(compiled[i].Error), outcomes[i].Plan!))
                .ToDictionary(x => x.f, x => (x.Item2, x.Item3));
        }

        internal Dictionary<string, (CompiledKernel Kernel, BindingPointPlan Plan)> ByFrame { get; }

        public void Dispose() => _folder.Dispose();
    }

    private readonly Kernels _kernels;

    public GaBenchmarkOperations_MatchEngine(Kernels kernels) => _kernels = kernels;

    public static IEnumerable<object[]> FrameNames() => Frames.Select(f => new object[] { f });

    [Theory]
    [MemberData(nameof(FrameNames))]
    public void Every_operation_matches_the_numeric_engine(string frame)
    {
        var (kernel, plan) = _kernels.ByFrame[frame];
        var result = RegionVerifier.Verify(kernel, plan, [], [], 1e-7, seed: 11, samples: 8);
        Assert.True(result.Passed, result.Failure);
    }

    [Theory]
    [MemberData(nameof(FrameNames))]
    public void The_generated_general_inverse_times_its_argument_is_one(string frame)
    {
        var (kernel, plan) = _kernels.ByFrame[frame];
        var random = new Random(frame.Length * 17 + frame[^1]);
        var input = new double[kernel.Inputs.Count];
        var output = new double[kernel.Outputs.Count];
        for (var sample = 0; sample < 8; sample++)
        {
            for (var i = 0; i < input.Length; i++) input[i] = random.NextDouble() * 3 - 1.5;
            kernel.Run(input, output);
            for (var j = 0; j < output.Length; j++)
            {
                if (!kernel.Outputs[j].StartsWith("r_one.", StringComparison.Ordinal)) continue;
                var expected = kernel.Outputs[j] == "r_one.1" ? 1.0 : 0.0;
                Assert.True(Math.Abs(output[j] - expected) < 1e-8, $"{frame}: {kernel.Outputs[j]} = {output[j]}");
            }
        }
    }
}
