using System.Reflection;
using System.Runtime.Loader;
using System.Text;
using GMac.Core.CodeGeneration;
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

    /// <summary>The block with inputs and outputs moved to array slots (verbatim output text dropped).</summary>
    public static (CodeBlock Block, List<string> Inputs, List<string> Outputs) Remap(CodeBlock block, IEnumerable<string> inputNames)
    {
        var inputs = inputNames.ToList();
        var outputs = block.OutputTargets.Keys.Order(StringComparer.Ordinal).ToList();
        var inputText = inputs.Select((name, i) => (name, i)).ToDictionary(x => x.name, x => $"__in[{x.i}]", StringComparer.Ordinal);
        var outputText = outputs.Select((name, j) => (name, j)).ToDictionary(x => x.name, x => $"__out[{x.j}]", StringComparer.Ordinal);
        var statements = block.Statements.Where(s => s is not VerbatimStatement);
        return (new CodeBlock(statements, inputText, outputText), inputs, outputs);
    }

    /// <summary>
    /// Compiles the blocks together (one compilation is much cheaper than many); returns a kernel or
    /// the compiler's first error for each block.
    /// </summary>
    /// <param name="scalarTypes">The scalar type of each block (<c>double</c> or <c>float</c>); all double when null.</param>
    public static IReadOnlyList<(CompiledKernel? Kernel, string? Error)> Compile(IReadOnlyList<(CodeBlock Block, List<string> Inputs, List<string> Outputs)> blocks,
        IReadOnlyList<string>? scalarTypes = null)
    {
        string TypeOf(int k) => scalarTypes?[k] ?? "double";
        var sources = blocks.Select((b, k) => Source(b.Block, k, TypeOf(k))).ToList();
        if (TryCompile(sources, out var assembly, out _))
            return blocks.Select((b, k) => ((CompiledKernel?)Load(assembly!, k, b.Inputs, b.Outputs, TypeOf(k)), (string?)null)).ToList();
        // Something does not compile: find which, one block at a time.
        return blocks.Select((b, k) => TryCompile([sources[k]], out var single, out var error)
            ? ((CompiledKernel?)Load(single!, k, b.Inputs, b.Outputs, TypeOf(k)), (string?)null)
            : (null, error)).ToList();
    }

    private static string Source(CodeBlock block, int index, string scalarType)
    {
        var body = CSharpEmitter.Emit(block, new CSharpEmitOptions
        {
            Indent = "        ", NewLine = "\n", ScalarType = scalarType, IsNameTaken = n => n.StartsWith("__", StringComparison.Ordinal),
        });
        var sb = new StringBuilder();
        sb.Append("public static class GMacVerify").Append(index).Append("\n{\n");
        sb.Append("    public static void Run(").Append(scalarType).Append("[] __in, ").Append(scalarType).Append("[] __out)\n    {\n");
        sb.Append(body);
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
        if (scalarType != "float") return new CompiledKernel(method.CreateDelegate<Action<double[], double[]>>(), inputs, outputs);
        var run = method.CreateDelegate<Action<float[], float[]>>();
        // Inputs are rounded to float on the way in; outputs left unassigned stay NaN, as in a double kernel.
        return new CompiledKernel((input, output) =>
        {
            var singleInput = Array.ConvertAll(input, x => (float)x);
            var singleOutput = new float[output.Length];
            Array.Fill(singleOutput, float.NaN);
            run(singleInput, singleOutput);
            for (var j = 0; j < output.Length; j++) output[j] = singleOutput[j];
        }, inputs, outputs) { IsSingle = true };
    }
}
