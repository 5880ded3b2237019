using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;

namespace GMac.CSharp.Tests.Support;

/// <summary>Compiles C# files with Roslyn against the framework, as an independent check that generated code builds.</summary>
internal static class CSharpCompile
{
    private static readonly Lazy<MetadataReference[]> References = new(() =>
    {
        var framework = Path.GetDirectoryName(typeof(object).Assembly.Location)!;
        return Directory.EnumerateFiles(framework, "System*.dll")
            .Where(p => !p.EndsWith(".Native.dll", StringComparison.OrdinalIgnoreCase))
            .Select(p => (MetadataReference)MetadataReference.CreateFromFile(p))
            .ToArray();
    });

    /// <summary>The compiler's errors for the files, each as "path(line,col): CSxxxx message".</summary>
    public static IReadOnlyList<string> Errors(params string[] paths) =>
        Compilation(paths).GetDiagnostics().Where(d => d.Severity == DiagnosticSeverity.Error).Select(d => d.ToString()).ToList();

    /// <summary>The files compiled (optimized, as a release build runs them) and loaded, to run the code in them.</summary>
    public static System.Reflection.Assembly Load(params string[] paths)
    {
        using var stream = new MemoryStream();
        var result = Compilation(paths).Emit(stream);
        Assert.True(result.Success, string.Join("\n", result.Diagnostics.Where(d => d.Severity == DiagnosticSeverity.Error)));
        stream.Position = 0;
        return new System.Runtime.Loader.AssemblyLoadContext("gmac-test", isCollectible: true).LoadFromStream(stream);
    }

    private static CSharpCompilation Compilation(string[] paths)
    {
        var options = new CSharpParseOptions(LanguageVersion.Latest);
        var trees = paths.Select(p => CSharpSyntaxTree.ParseText(File.ReadAllText(p), options, p))
            .Append(CSharpSyntaxTree.ParseText("global using System;", options));
        return CSharpCompilation.Create("Check", trees, References.Value,
            new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary, optimizationLevel: OptimizationLevel.Release));
    }
}
