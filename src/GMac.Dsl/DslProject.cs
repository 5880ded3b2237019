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

    /// <summary>
    /// The DSL text at <paramref name="span"/>, its line breaks and indentation folded to single
    /// spaces and long texts cut at <paramref name="maxLength"/>; null where the span has no text.
    /// Messages quote it to show an expression as the user wrote it.
    /// </summary>
    public string? SourceText(SourceSpan span, int maxLength = 120)
    {
        if (span.Length <= 0 || SyntaxTrees.FirstOrDefault(t => t.FilePath == span.FilePath) is not { } tree) return null;
        if (span.Start < 0 || span.Start + span.Length > tree.Text.Length) return null;
        var text = string.Join(' ', tree.Text.Substring(span.Start, span.Length).Split((char[]?)null, StringSplitOptions.RemoveEmptyEntries));
        return text.Length <= maxLength ? text : text[..(maxLength - 1)] + "…";
    }

    /// <summary>Wall time of parsing and binding, without reading the files.</summary>
    public TimeSpan ParseAndBindTime { get; }

    /// <summary>Every <c>*.gmac</c> file under <paramref name="directory"/>.</summary>
    public static DslProject Load(string directory) => Load([directory]);

    /// <summary>
    /// The <c>*.gmac</c> files of several sources bound as one project: each source is a folder
    /// (all its <c>*.gmac</c> files, recursively) or one file. A file reached twice (the same
    /// file named again, or under two folders given) is read once.
    /// </summary>
    public static DslProject Load(IReadOnlyList<string> sources)
    {
        var files = new List<(string Path, string Text)>();
        var bag = new DiagnosticBag();
        var paths = new List<string>();
        var seen = new HashSet<string>(StringComparer.Ordinal);
        foreach (var source in sources)
        {
            if (File.Exists(source))
            {
                if (!source.EndsWith(".gmac", StringComparison.OrdinalIgnoreCase))
                    bag.ReportCannotRead(SourceSpan.None(source), $"'{source}' is a file, not a DSL folder or a .gmac file: name the folder that holds the .gmac files (here '{Path.GetDirectoryName(Path.GetFullPath(source))}') or the .gmac files themselves");
                else if (SourceTree.WhyNotReadable(source) is { } why) bag.ReportCannotRead(SourceSpan.None(source), why);
                else if (seen.Add(RealPath.Of(source))) paths.Add(source);
                continue;
            }
            if (!Directory.Exists(source))
            {
                bag.ReportCannotRead(SourceSpan.None(source), $"DSL folder or file '{source}' does not exist");
                continue;
            }
            var listing = SourceTree.List(source, "*.gmac");
            foreach (var skipped in listing.Skipped)
            {
                if (skipped.IsError) bag.ReportCannotRead(SourceSpan.None(skipped.Path), skipped.Reason);
                else bag.ReportSkippedFile(SourceSpan.None(skipped.Path), skipped.Reason);
            }
            if (listing.Files.Count == 0) bag.ReportCannotRead(SourceSpan.None(source), $"no *.gmac files in '{source}'");
            paths.AddRange(listing.Files.Where(f => seen.Add(RealPath.Of(f))));
        }
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
