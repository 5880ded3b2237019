using System.Diagnostics;
using GMac.Dsl.Diagnostics;
using GMac.Dsl.Semantics;
using GMac.Dsl.Syntax;
using SafeFiles;

namespace GMac.Dsl;

/// <summary>
/// A GMacDSL project: every <c>*.gmac</c> file under a folder, parsed and bound
/// together so that definitions resolve by name whatever file holds them.
/// </summary>
public sealed class DslProject
{
    private DslProject(IReadOnlyList<SyntaxTree> trees, SemanticModel model, IReadOnlyList<Diagnostic> diagnostics, TimeSpan elapsed)
    {
        SyntaxTrees = trees;
        Model = model;
        Diagnostics = diagnostics;
        ParseAndBindTime = elapsed;
    }

    public IReadOnlyList<SyntaxTree> SyntaxTrees { get; }
    public SemanticModel Model { get; }
    public IReadOnlyList<Diagnostic> Diagnostics { get; }
    public bool HasErrors => Diagnostics.Any(d => d.IsError);

    /// <summary>Wall time of parsing and binding, without reading the files.</summary>
    public TimeSpan ParseAndBindTime { get; }

    public static DslProject Load(string directory)
    {
        var files = new List<(string Path, string Text)>();
        var bag = new DiagnosticBag();
        if (!Directory.Exists(directory))
        {
            bag.ReportCannotRead(SourceSpan.None(directory), $"DSL folder '{directory}' does not exist");
            return FromSources(files, bag.Items);
        }
        var listing = SourceTree.List(directory, "*.gmac");
        foreach (var skipped in listing.Skipped)
        {
            if (skipped.IsError) bag.ReportCannotRead(SourceSpan.None(skipped.Path), skipped.Reason);
            else bag.ReportSkippedFile(SourceSpan.None(skipped.Path), skipped.Reason);
        }
        var paths = listing.Files;
        if (paths.Count == 0) bag.ReportCannotRead(SourceSpan.None(directory), $"no *.gmac files in '{directory}'");
        foreach (var path in paths)
        {
            try
            {
                files.Add((path, File.ReadAllText(path)));
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                bag.ReportCannotRead(SourceSpan.None(path), $"cannot read file: {e.Message}");
            }
        }
        return FromSources(files, bag.Items);
    }

    /// <summary>Parses and binds in-memory sources (path, text).</summary>
    public static DslProject FromSources(IEnumerable<(string Path, string Text)> sources, IReadOnlyList<Diagnostic>? earlier = null)
    {
        var watch = Stopwatch.StartNew();
        var trees = sources.Select(s => SyntaxTree.Parse(s.Path, s.Text)).ToList();
        var model = Binder.Bind(trees);
        foreach (var tree in trees) tree.ReleaseRoot();
        watch.Stop();
        var diagnostics = (earlier ?? []).Concat(model.Diagnostics)
            .OrderBy(d => d.Span.FilePath, StringComparer.Ordinal)
            .ThenBy(d => d.Span.Line).ThenBy(d => d.Span.Column)
            .ToList();
        return new DslProject(trees, model, diagnostics, watch.Elapsed);
    }
}
