using System.Text;
using System.Text.RegularExpressions;
using GMac.CSharp.BindingPoints;
using GMac.CSharp.Emit;
using GMac.CSharp.Tests.Support;
using GMac.Dsl;
using GMac.Dsl.Diagnostics;

namespace GMac.Cli.Tests.Docs;

/// <summary>
/// The examples of README.md and docs/*.md are what the tools accept and write: every ```gmac block
/// checks against the dsl/ library (a ```gmac fragment is skipped), every C# binding point generates,
/// and one shown with its generated code shows exactly what <c>gmac generate</c> writes. The language
/// reference names every construct of the grammar and every operator and built-in function.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed partial class Documentation_Examples
{
    /// <summary>The library's files, read once for all blocks.</summary>
    private static readonly Lazy<List<(string Path, string Text)>> Library = new(() =>
        Directory.EnumerateFiles(SharedDsl.DslDirectory, "*.gmac", SearchOption.AllDirectories)
            .Order(StringComparer.Ordinal)
            .Select(p => (p, File.ReadAllText(p)))
            .ToList());

    [Fact]
    public void Every_gmac_block_is_a_file_gmac_check_accepts()
    {
        var failures = new StringBuilder();
        foreach (var block in MarkdownCodeBlock.All().Where(IsGmacFile))
        {
            if (Check(block) is { } errors) failures.Append(block.Where).Append(": this ```gmac block is not accepted by gmac check (mark a deliberate fragment ```gmac fragment):\n").Append(errors);
        }
        Assert.True(failures.Length == 0, failures.ToString());
    }

    [Fact]
    public void Every_csharp_binding_point_generates_and_shows_what_gmac_generate_writes()
    {
        var blocks = MarkdownCodeBlock.All();
        var shown = blocks.Where(b => b.Language is "csharp" or "cs" or "c#" && b.Text.Contains("#region GMac", StringComparison.Ordinal)).ToList();
        // Generated on both cores as gmac generate does with files, then reported in document order.
        var results = new (int Points, string Failures)[shown.Count];
        Parallel.For(0, shown.Count, i => results[i] = CheckBindingPoints(shown[i], blocks));
        var failures = string.Concat(results.Select(r => r.Failures));
        Assert.True(failures.Length == 0, failures);
        Assert.True(results.Sum(r => r.Points) > 0, "no binding point found in README.md or docs/*.md (docs/cookbook.md shows one per macro)");
    }

    /// <summary>The block's binding points generate; a region shown with code shows what gmac generate writes, with or without --stats.</summary>
    private static (int Points, string Failures) CheckBindingPoints(MarkdownCodeBlock block, IReadOnlyList<MarkdownCodeBlock> blocks)
    {
        var failures = new StringBuilder();
        var file = BindingPointReader.Read(SourceText.FromString(block.Where, WithUsingsOfItsFile(block, blocks)));
        var generation = BindingPointGenerator.Generate(file, ContextFor(block, file, blocks), includeStatistics: true);
        if (!generation.Succeeded)
        {
            failures.Append(block.Where).Append(": the binding point does not generate:\n");
            foreach (var d in generation.Diagnostics) failures.Append("  block line ").Append(d.Span.Line).Append(": ").Append(d.Code).Append(' ').Append(d.Message).Append('\n');
            return (file.Points.Count, failures.ToString());
        }
        foreach (var region in generation.Regions)
        {
            var body = Body(file, region.Point);
            if (body.Trim().Length == 0) continue; // a binding point before generation
            var code = region.Code!;
            if (body != code && body != WithoutStatistics(code))
                failures.Append(block.Where).Append(": the region of '").Append(region.Point.MacroName).Append("' (block line ").Append(region.Point.RegionLineNumber)
                    .Append(") differs from what gmac generate writes:\n--- shown\n").Append(body).Append("--- generated\n").Append(WithoutStatistics(code));
        }
        return (file.Points.Count, failures.ToString());
    }

    /// <summary>
    /// A block that shows a region alone ("after gmac generate") stands for that region in the file of
    /// the C# block before it: it is read with that block's <c>using</c> lines, on one line before its
    /// first (the vector code names its types short only where the file imports them).
    /// </summary>
    private static string WithUsingsOfItsFile(MarkdownCodeBlock block, IReadOnlyList<MarkdownCodeBlock> blocks)
    {
        if (!block.Text.TrimStart().StartsWith("#region GMac", StringComparison.Ordinal)) return block.Text;
        var file = blocks.LastOrDefault(b => b.File == block.File && b.Line < block.Line && b.Language is "csharp" or "cs" or "c#"
            && !b.Text.TrimStart().StartsWith("#region GMac", StringComparison.Ordinal));
        if (file is null) return block.Text;
        var usings = file.Text.Split('\n').Select(l => l.Trim()).Where(l => l.StartsWith("using ", StringComparison.Ordinal) && l.EndsWith(';'));
        return string.Join(" ", usings) + "\n" + block.Text;
    }

    [Fact]
    public void Language_reference_names_every_construct_of_the_grammar()
    {
        var language = ReadLanguageReference();
        var spans = InlineCode().Matches(language).Select(m => m.Groups[1].Value.Trim()).ToHashSet(StringComparer.Ordinal);
        var missing = GrammarConstructs().Where(c => !spans.Contains(c)).ToList();
        Assert.True(missing.Count == 0,
            $"docs/language.md does not name these constructs of src/GMac.Dsl/Syntax/GMacDsl.g4 (write each as inline code, e.g. a heading 'Frames (`frameDefinition`)'): {string.Join(", ", missing)}");
    }

    [Fact]
    public void Language_reference_names_every_operator_and_built_in_function()
    {
        var language = ReadLanguageReference();
        var algebra = Directory.EnumerateFiles(Path.Combine(SharedDsl.RepositoryRoot, "docs"), "algebra-*.md").Select(File.ReadAllText);
        var words = new HashSet<string>(StringComparer.Ordinal);
        foreach (var text in algebra.Prepend(language))
        {
            foreach (Match m in InlineCode().Matches(text)) words.UnionWith(Words(m.Groups[1].Value));
            foreach (Match m in FencedCode().Matches(text)) words.UnionWith(Words(m.Groups[1].Value));
        }
        var names = OperatorKeywords().Concat(Dsl.Semantics.Binder.BuiltinNames).Distinct(StringComparer.Ordinal).ToList();
        Assert.True(names.Count > 20, $"only {names.Count} operator and function names found");
        var missing = names.Where(n => !words.Contains(n)).ToList();
        Assert.True(missing.Count == 0,
            $"docs/language.md (or docs/algebra-*.md) does not mention these operators or built-in functions in code: {string.Join(", ", missing)}");
    }

    /// <summary>
    /// Rules of the grammar that are not constructs a user writes as such, and why; every other
    /// parser rule and labelled alternative must be named in docs/language.md.
    /// </summary>
    private static readonly Dictionary<string, string> NotUserConstructs = new(StringComparer.Ordinal)
    {
        ["compilationUnit"] = "the file as a whole: a sequence of definitions, described under `definition`",
        ["matrixRow"] = "one row of a `matrix`",
        ["name"] = "an identifier (keywords that stay usable as names are a lexical detail)",
        ["qualifiedName"] = "a dotted name such as e3d.Vector, used inside other constructs",
        ["number"] = "a numeric literal",
        ["parenExpr"] = "parentheses, described with precedence",
    };

    /// <summary>The parser rules and labelled alternatives of GMacDsl.g4, read from the grammar file.</summary>
    private static List<string> GrammarConstructs()
    {
        var grammar = File.ReadAllText(Path.Combine(SharedDsl.RepositoryRoot, "src", "GMac.Dsl", "Syntax", "GMacDsl.g4"));
        var rules = ParserRule().Matches(grammar).Select(m => m.Groups[1].Value);
        var labels = Label().Matches(grammar).Select(m => m.Groups[1].Value);
        var all = rules.Concat(labels).Distinct(StringComparer.Ordinal).ToList();
        Assert.True(all.Count > 40, $"only {all.Count} rules read from the grammar");
        foreach (var excluded in NotUserConstructs.Keys) Assert.Contains(excluded, all);
        return all.Where(r => !NotUserConstructs.ContainsKey(r)).ToList();
    }

    /// <summary>The words of the product operators (<c>gp</c>, <c>op</c>, …): the literals of the tokens of the grammar's product alternative.</summary>
    private static IEnumerable<string> OperatorKeywords()
    {
        var grammar = File.ReadAllText(Path.Combine(SharedDsl.RepositoryRoot, "src", "GMac.Dsl", "Syntax", "GMacDsl.g4"));
        var tokens = ProductTokens().Match(grammar).Groups[1].Value.Split('|', StringSplitOptions.TrimEntries);
        var keywords = tokens.Select(t => Regex.Match(grammar, $@"^{t}\s*:\s*'(\w+)'\s*;", RegexOptions.Multiline).Groups[1].Value).ToList();
        Assert.True(keywords.Count >= 10 && keywords.All(k => k.Length > 0), $"product operators not read from the grammar: {string.Join(", ", tokens)}");
        return keywords;
    }

    private static string ReadLanguageReference()
    {
        var path = Path.Combine(SharedDsl.RepositoryRoot, "docs", "language.md");
        Assert.True(File.Exists(path), "docs/language.md does not exist: the GMacDSL reference must name every construct of the grammar, operator and built-in function");
        return File.ReadAllText(path);
    }

    private static IEnumerable<string> Words(string code) => Word().Matches(code).Select(m => m.Value);

    private static bool IsGmacFile(MarkdownCodeBlock block) => block.Language == "gmac" && !block.Info.Skip(1).Contains("fragment");

    /// <summary>Null when the block checks without errors against the library (or, when it defines what the library does, alone); else the errors.</summary>
    private static string? Check(MarkdownCodeBlock block)
    {
        var withLibrary = Errors(DslProject.FromSources([.. Library.Value, (block.Where, block.Text)]));
        if (withLibrary.Count == 0) return null;
        var alone = Errors(DslProject.FromSources([(block.Where, block.Text)]));
        if (alone.Count == 0) return null;
        var blockErrors = withLibrary.Where(d => d.Span.FilePath == block.Where).ToList();
        return string.Concat((blockErrors.Count > 0 ? blockErrors : withLibrary).Select(d => $"  {Describe(block, d)}\n"));
    }

    private static List<Diagnostic> Errors(DslProject project) => OutputBlockCheck.Diagnostics(project).Where(d => d.IsError).ToList();

    /// <summary>A diagnostic with its line in the Markdown file when it is in the block.</summary>
    private static string Describe(MarkdownCodeBlock block, Diagnostic d) =>
        d.Span.FilePath == block.Where ? $"{block.File}:{block.Line + d.Span.Line}:{d.Span.Column}: {d.Code}: {d.Message}" : d.ToString();

    /// <summary>
    /// The library's context, unless a region names a macro the library does not define: then the
    /// library with the ```gmac block of the same file that defines it (the nearest before the region).
    /// </summary>
    private static GenerationContext ContextFor(MarkdownCodeBlock block, BindingPointFile file, IReadOnlyList<MarkdownCodeBlock> blocks)
    {
        var library = SharedDsl.Context;
        var missing = file.Points.Select(p => p.MacroName).FirstOrDefault(m => !library.Project.Model.Macros.ContainsKey(m));
        if (missing is null) return library;
        var definer = blocks
            .Where(b => b.File == block.File && IsGmacFile(b) && Regex.IsMatch(b.Text, $@"\bdefine\s+macro\s+{Regex.Escape(missing)}\b"))
            .OrderBy(b => b.Line < block.Line ? block.Line - b.Line : int.MaxValue - b.Line)
            .FirstOrDefault();
        if (definer is null) return library;
        var project = DslProject.FromSources([.. Library.Value, (definer.Where, definer.Text)]);
        if (project.HasErrors) project = DslProject.FromSources([(definer.Where, definer.Text)]);
        return new GenerationContext(project, cacheDirectory: null);
    }

    /// <summary>The lines of a region that are not binding lines, as the block shows them.</summary>
    private static string Body(BindingPointFile file, BindingPoint point) =>
        string.Concat(Enumerable.Range(point.RegionLine + 1, point.EndRegionLine - point.RegionLine - 1)
            .Select(i => file.Lines[i])
            .Where(l => !BindingLineReader.IsBindingLine(l)));

    private static string WithoutStatistics(string code)
    {
        var end = code.IndexOf('\n', StringComparison.Ordinal);
        return end >= 0 && code.TrimStart().StartsWith("// GMac: ", StringComparison.Ordinal) ? code[(end + 1)..] : code;
    }

    [GeneratedRegex(@"^([a-z]\w*)\s*\n\s*:", RegexOptions.Multiline)]
    private static partial Regex ParserRule();

    [GeneratedRegex(@"#\s*([a-z]\w*)\s*$", RegexOptions.Multiline)]
    private static partial Regex Label();

    [GeneratedRegex(@"op = \((GP[^)]*)\)")]
    private static partial Regex ProductTokens();

    [GeneratedRegex(@"(?<!`)`([^`\n]+)`(?!`)")]
    private static partial Regex InlineCode();

    [GeneratedRegex(@"^\s*(?:```|~~~)[^\n]*\n(.*?)^\s*(?:```|~~~)", RegexOptions.Multiline | RegexOptions.Singleline)]
    private static partial Regex FencedCode();

    [GeneratedRegex(@"[A-Za-z_][A-Za-z_0-9]*")]
    private static partial Regex Word();
}
