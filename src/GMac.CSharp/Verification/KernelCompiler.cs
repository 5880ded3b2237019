using System.Reflection;
using System.Runtime.Loader;
using System.Text;
using GMac.Core.CodeGeneration;
using GMac.CSharp.BindingPoints;
using GMac.CSharp.Emit;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;

namespace GMac.CSharp.Verification;

/// <summary>
/// Compiles generated blocks in memory with Roslyn: each block's inputs are remapped to
/// <c>__in[i]</c> and its outputs to <c>__out[j]</c>, so the statements are exactly those
/// written into the source, only reading and writing arrays.
/// </summary>
internal static class KernelCompiler
{
    private static readonly Lazy<MetadataReference[]> References = new(() =>
    {
        var tpa = ((string?)AppContext.GetData("TRUSTED_PLATFORM_ASSEMBLIES") ?? "").Split(Path.PathSeparator);
        return tpa.Where(p => Path.GetFileName(p) is "System.Runtime.dll" or "System.Private.CoreLib.dll")
            .Select(p => (MetadataReference)MetadataReference.CreateFromFile(p))
            .ToArray();
    });

    /// <summary>
    /// The block with inputs and outputs moved to array slots (verbatim output text dropped). An output
    /// bound to the same storage as an input shares its slot, and holding outputs back is decided on the
    /// original texts (<paramref name="names"/> as in the region's scope), so the kernel runs the
    /// code as it is written into the file, with the aliasing it has there.
    /// </summary>
    public static KernelBlock Remap(CodeBlock block, IEnumerable<string> inputNames, StorageNames? names = null)
    {
        var inputs = inputNames.ToList();
        var outputs = block.OutputTargets.Keys.Order(StringComparer.Ordinal).ToList();
        var inputText = inputs.Select((name, i) => (name, i)).ToDictionary(x => x.name, x => $"__in[{x.i}]", StringComparer.Ordinal);
        var inPlace = new Dictionary<int, int>();
        var outputText = new Dictionary<string, string>(StringComparer.Ordinal);
        for (var j = 0; j < outputs.Count; j++)
        {
            var target = block.OutputTargets[outputs[j]];
            var slot = inputs.FindIndex(name => block.InputText.TryGetValue(name, out var text) && BindingExpressions.SameStorage(target, text));
            if (slot >= 0) inPlace[j] = slot;
            outputText[outputs[j]] = slot >= 0 ? $"__in[{slot}]" : $"__out[{j}]";
        }
        var statements = block.Statements.Where(s => s is not VerbatimStatement);
        return new KernelBlock(new CodeBlock(statements, inputText, outputText), inputs, outputs)
        {
            MayOverwrite = BindingExpressions.Overwrites(block, names),
            InPlace = inPlace,
        };
    }

    /// <summary>
    /// Compiles the blocks together (one compilation is much cheaper than many); returns a kernel or
    /// the compiler's first error for each block.
    /// </summary>
    /// <param name="scalarTypes">The scalar type of each block (<c>double</c>, <c>float</c>, <c>Vector256&lt;double&gt;</c>, …); all double when null.</param>
    public static IReadOnlyList<(CompiledKernel? Kernel, string? Error)> Compile(IReadOnlyList<KernelBlock> blocks,
        IReadOnlyList<string>? scalarTypes = null)
    {
        string TypeOf(int k) => scalarTypes?[k] ?? "double";
        var sources = blocks.Select((b, k) => Source(b, k, TypeOf(k))).ToList();
        if (TryCompile(sources, out var assembly, out _))
            return blocks.Select((b, k) => ((CompiledKernel?)Load(assembly!, k, b.Inputs, b.Outputs, TypeOf(k)), (string?)null)).ToList();
        // Something does not compile: find which, one block at a time.
        return blocks.Select((b, k) => TryCompile([sources[k]], out var single, out var error)
            ? ((CompiledKernel?)Load(single!, k, b.Inputs, b.Outputs, TypeOf(k)), (string?)null)
            : (null, error)).ToList();
    }

    private static string Source(KernelBlock kernel, int index, string scalarType)
    {
        var body = CSharpEmitter.Emit(kernel.Block, new CSharpEmitOptions
        {
            Indent = "        ", NewLine = "\n", ScalarType = scalarType, IsNameTaken = n => n.StartsWith("__", StringComparison.Ordinal),
            MayOverwrite = kernel.MayOverwrite, FusedMultiplyAdd = kernel.FusedMultiplyAdd,
        });
        foreach (var (output, input) in kernel.InPlace) body += $"        __out[{output}] = __in[{input}];\n";
        var sb = new StringBuilder();
        if (VectorType.Find(scalarType) is { } vector)
        {
            // Each vector slot is loaded from, and stored to, its run of lanes in the arrays.
            var (t, e) = (vector.Name, vector.Element);
            sb.Append("using System.Numerics;\nusing System.Runtime.Intrinsics;\n");
            sb.Append("public static class GMacVerify").Append(index).Append("\n{\n");
            sb.Append("    public static void Run(").Append(e).Append("[] __inLanes, ").Append(e).Append("[] __outLanes)\n    {\n");
            foreach (var side in new[] { "in", "out" })
            {
                sb.Append($"        var __{side} = new {t}[__{side}Lanes.Length / {t}.Count];\n");
                sb.Append($"        for (var __k = 0; __k < __{side}.Length; __k++) __{side}[__k] = {vector.Family}.Create(new ReadOnlySpan<{e}>(__{side}Lanes, __k * {t}.Count, {t}.Count));\n");
            }
            sb.Append(body);
            sb.Append($"        for (var __k = 0; __k < __out.Length; __k++) __out[__k].CopyTo(new Span<{e}>(__outLanes, __k * {t}.Count, {t}.Count));\n");
        }
        else
        {
            sb.Append("public static class GMacVerify").Append(index).Append("\n{\n");
            sb.Append("    public static void Run(").Append(scalarType).Append("[] __in, ").Append(scalarType).Append("[] __out)\n    {\n");
            sb.Append(body);
        }
        sb.Append("    }\n}\n");
        return sb.ToString();
    }

    private static bool TryCompile(IReadOnlyList<string> sources, out Assembly? assembly, out string? error)
    {
        var options = new CSharpParseOptions(LanguageVersion.Latest);
        var trees = sources.Select(s => CSharpSyntaxTree.ParseText("using System;\n" + s, options));
        var compilation = CSharpCompilation.Create($"GMacVerify{Guid.NewGuid():N}", trees, References.Value,
            new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary, optimizationLevel: OptimizationLevel.Release));
        using var stream = new MemoryStream();
        var result = compilation.Emit(stream);
        if (!result.Success)
        {
            assembly = null;
            error = result.Diagnostics.FirstOrDefault(d => d.Severity == DiagnosticSeverity.Error)?.ToString() ?? "compilation failed";
            return false;
        }
        stream.Position = 0;
        assembly = new AssemblyLoadContext("gmac-verify", isCollectible: true).LoadFromStream(stream);
        error = null;
        return true;
    }

    private static CompiledKernel Load(Assembly assembly, int index, List<string> inputs, List<string> outputs, string scalarType)
    {
        var method = assembly.GetType($"GMacVerify{index}")!.GetMethod("Run")!;
        var lanes = VectorType.Find(scalarType)?.Lanes ?? 1;
        if (!CSharpEmitter.IsSingle(scalarType)) return new CompiledKernel(method.CreateDelegate<Action<double[], double[]>>(), inputs, outputs) { Lanes = lanes };
        var run = method.CreateDelegate<Action<float[], float[]>>();
        // Inputs are rounded to float on the way in; outputs left unassigned stay NaN, as in a double kernel.
        return new CompiledKernel((input, output) =>
        {
            var singleInput = Array.ConvertAll(input, x => (float)x);
            var singleOutput = new float[output.Length];
            Array.Fill(singleOutput, float.NaN);
            run(singleInput, singleOutput);
            for (var j = 0; j < output.Length; j++) output[j] = singleOutput[j];
        }, inputs, outputs) { IsSingle = true, Lanes = lanes };
    }
}
