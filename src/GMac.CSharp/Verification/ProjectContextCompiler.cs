using System.Text.RegularExpressions;
using GMac.CSharp.BindingPoints;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;
using DiagnosticCodes = GMac.Dsl.Diagnostics.DiagnosticCodes;
using SourceSpan = GMac.Dsl.Diagnostics.SourceSpan;

namespace GMac.CSharp.Verification;

/// <summary>
/// Compiles generated regions where they belong: each file with its new region bodies spliced in,
/// together with the other C# files of its project (the nearest folder above it holding a
/// <c>.csproj</c>, else the other files of its own folder) against the framework of the running runtime. Only errors inside a region body
/// count: the rest of the project may use packages or other projects this compilation lacks.
/// </summary>
internal static partial class ProjectContextCompiler
{
    private static readonly CSharpParseOptions ParseOptions = new(LanguageVersion.Latest);

    /// <summary>The global usings the .NET SDK adds when a project enables implicit usings.</summary>
    private const string ImplicitUsings =
        "global using System; global using System.Collections.Generic; global using System.IO; global using System.Linq; " +
        "global using System.Net.Http; global using System.Threading; global using System.Threading.Tasks;";

    private static readonly Lazy<MetadataReference[]> FrameworkReferences = new(() =>
    {
        // The trusted platform assemblies of the runtime's own folder: the framework, not this tool's dependencies.
        var framework = Path.GetDirectoryName(typeof(object).Assembly.Location)!;
        var tpa = ((string?)AppContext.GetData("TRUSTED_PLATFORM_ASSEMBLIES") ?? "").Split(Path.PathSeparator, StringSplitOptions.RemoveEmptyEntries);
        return tpa.Where(p => string.Equals(Path.GetDirectoryName(p), framework, StringComparison.Ordinal))
            .Select(p => (MetadataReference)MetadataReference.CreateFromFile(p))
            .ToArray();
    });

    public static IReadOnlyList<RegionCompileFailure> Check(IReadOnlyList<FileGeneration> generations)
    {
        var failures = new List<RegionCompileFailure>();
        foreach (var project in generations.GroupBy(g => ProjectFile(g.File.Path) ?? Path.GetDirectoryName(Path.GetFullPath(g.File.Path))!, StringComparer.Ordinal))
            failures.AddRange(CheckProject(project.Key, project.ToList()));
        return failures;
    }

    /// <param name="project">A <c>.csproj</c> file, or the folder standing for a project when there is none.</param>
    private static IEnumerable<RegionCompileFailure> CheckProject(string project, IReadOnlyList<FileGeneration> generations)
    {
        var spliced = generations.Select(g =>
        {
            var bodies = new List<(GeneratedRegion Region, int Start, int End)>();
            var text = BindingPointGenerator.Splice(g.File, g.Regions, bodies);
            // Parsed as the reader parses it, so that lines in messages are the editor's lines.
            return (g.File.Path, Tree: CSharpSyntaxTree.ParseText(BindingPoints.SourceText.ForParsing(text), ParseOptions, Path.GetFullPath(g.File.Path)), Bodies: bodies);
        }).ToList();
        var ownPaths = spliced.Select(s => s.Tree.FilePath).ToHashSet(StringComparer.Ordinal);
        var trees = spliced.Select(s => s.Tree).ToList();
        var isProjectFile = File.Exists(project);
        foreach (var path in ProjectSources(isProjectFile ? Path.GetDirectoryName(project)! : project, recursive: isProjectFile).Where(p => !ownPaths.Contains(p)))
            if (TryRead(path) is { } text) trees.Add(CSharpSyntaxTree.ParseText(text, ParseOptions, path));
        // A folder outside any project is taken as new projects are made: with implicit usings.
        if (!isProjectFile || UsesImplicitUsings(project)) trees.Add(CSharpSyntaxTree.ParseText(ImplicitUsings, ParseOptions, "GMacImplicitUsings.g.cs"));
        var executable = trees.Any(t => t.GetRoot().ChildNodes().OfType<GlobalStatementSyntax>().Any());
        var compilation = CSharpCompilation.Create("GMacRegionCheck", trees, FrameworkReferences.Value,
            new CSharpCompilationOptions(executable ? OutputKind.ConsoleApplication : OutputKind.DynamicallyLinkedLibrary, allowUnsafe: true));

        foreach (var (path, tree, bodies) in spliced)
        {
            var model = compilation.GetSemanticModel(tree);
            foreach (var (region, start, end) in bodies)
            {
                var span = Microsoft.CodeAnalysis.Text.TextSpan.FromBounds(start, end);
                var error = model.GetDiagnostics(span)
                    .Where(d => d.Severity == DiagnosticSeverity.Error && d.Location.IsInSource && span.Contains(d.Location.SourceSpan.Start))
                    .OrderBy(d => d.Location.SourceSpan.Start)
                    .FirstOrDefault();
                if (error is null) continue;
                var at = error.Location.GetLineSpan().StartLinePosition;
                var statement = tree.GetText().Lines[at.Line].ToString().Trim();
                yield return new RegionCompileFailure(region, new GMac.Dsl.Diagnostics.Diagnostic(DiagnosticCodes.DoesNotCompileInProject, SourceSpan.At(path, at.Line + 1, at.Character + 1),
                    $"the code of '{region.Point.MacroName}' (region of line {region.Point.RegionLineNumber}) does not compile in its project: {error.Id}: {error.GetMessage()} in '{statement}'"));
            }
        }
    }

    /// <summary>The nearest <c>.csproj</c> in the file's folder or above it; null when there is none.</summary>
    private static string? ProjectFile(string path)
    {
        for (var folder = new DirectoryInfo(Path.GetDirectoryName(Path.GetFullPath(path))!); folder is not null; folder = folder.Parent)
        {
            var projects = SafeEnumerate(() => folder.GetFiles("*.csproj")).Select(f => f.FullName).Order(StringComparer.Ordinal).ToList();
            if (projects.Count > 0) return projects[0];
        }
        return null;
    }

    /// <summary>The C# files the SDK compiles by default: all under the project folder except bin/, obj/ and hidden folders.</summary>
    private static IEnumerable<string> ProjectSources(string folder, bool recursive)
    {
        var pending = new Stack<DirectoryInfo>([new DirectoryInfo(folder)]);
        while (pending.TryPop(out var directory))
        {
            foreach (var file in SafeEnumerate(() => directory.GetFiles("*.cs"))) yield return file.FullName;
            if (!recursive) yield break;
            foreach (var sub in SafeEnumerate(() => directory.GetDirectories()))
                if (sub.Name is not ("bin" or "obj") && !sub.Name.StartsWith('.')) pending.Push(sub);
        }
    }

    /// <summary>Whether the project, or the nearest Directory.Build.props above it when the project does not say, enables implicit usings.</summary>
    private static bool UsesImplicitUsings(string projectFile)
    {
        if (ImplicitUsingsSetting(TryRead(projectFile)) is { } own) return own;
        for (var folder = new DirectoryInfo(Path.GetDirectoryName(projectFile)!); folder is not null; folder = folder.Parent)
        {
            var props = Path.Combine(folder.FullName, "Directory.Build.props");
            if (File.Exists(props)) return ImplicitUsingsSetting(TryRead(props)) ?? false;
        }
        return false;
    }

    private static bool? ImplicitUsingsSetting(string? msbuild) =>
        msbuild is not null && ImplicitUsingsProperty().Match(msbuild) is { Success: true } m
            ? m.Groups[1].Value.Trim().ToLowerInvariant() is "enable" or "true"
            : null;

    private static string? TryRead(string path)
    {
        try
        {
            return File.ReadAllText(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return null;
        }
    }

    private static T[] SafeEnumerate<T>(Func<T[]> list)
    {
        try
        {
            return list();
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return [];
        }
    }

    [GeneratedRegex(@"<ImplicitUsings>([^<]*)</ImplicitUsings>", RegexOptions.IgnoreCase)]
    private static partial Regex ImplicitUsingsProperty();
}
