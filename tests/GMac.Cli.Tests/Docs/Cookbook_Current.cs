using GMac.CSharp.Docs;
using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.Docs;

/// <summary>docs/cookbook.md is what <c>gmac cookbook</c> writes from the library, and the command reports bad annotations.</summary>
[Collection(SharedDslCollection.Name)]
public sealed class Cookbook_Current
{
    /// <summary>The library's cookbook, built once for the tests that read it.</summary>
    private static readonly Lazy<(IReadOnlyList<CookbookGroup> Groups, IReadOnlyList<GMac.Dsl.Diagnostics.Diagnostic> Problems)> Built = new(() => Cookbook.Build(SharedDsl.Context));

    [Fact]
    public void Committed_cookbook_is_what_the_command_writes_from_the_library()
    {
        var (groups, problems) = Built.Value;
        Assert.True(problems.Count == 0, string.Join("\n", problems));
        var markdown = CookbookMarkdown.Write(groups, "dsl");
        var path = Path.Combine(SharedDsl.RepositoryRoot, "docs", "cookbook.md");
        var committed = File.Exists(path) ? File.ReadAllText(path).ReplaceLineEndings("\n") : "";
        if (committed == markdown) return;
        var expected = markdown.Split('\n');
        var actual = committed.Split('\n');
        var first = Enumerable.Range(0, Math.Min(expected.Length, actual.Length)).FirstOrDefault(i => expected[i] != actual[i], Math.Min(expected.Length, actual.Length));
        Assert.Fail($"docs/cookbook.md is out of date (first difference at line {first + 1}: " +
            $"committed '{(first < actual.Length ? actual[first] : "<end>")}', now '{(first < expected.Length ? expected[first] : "<end>")}'); run: {CookbookMarkdown.Command}");
    }

    [Fact]
    public void Every_macro_of_the_library_is_in_exactly_one_group()
    {
        var (groups, problems) = Built.Value;
        Assert.Empty(problems);
        var shown = groups.SelectMany(g => g.Entries.Select(e => e.Macro.Name)).ToList();
        Assert.Equal(shown.Count, shown.Distinct(StringComparer.Ordinal).Count());
        Assert.Equal(SharedDsl.Context.Project.Model.Macros.Keys.Order(StringComparer.Ordinal), shown.Order(StringComparer.Ordinal));
        Assert.True(groups.Count >= 8, $"only {groups.Count} groups");
    }

    [Theory]
    [InlineData("// cookbook bind: u=NoSuchBinding\n", 7, "no class binding 'NoSuchBinding'")]
    [InlineData("// cookbook bind: x=V\n", 7, "has no input or output 'x'")]
    [InlineData("// cookbook frobnicate: yes\n", 7, "unknown cookbook key 'frobnicate'")]
    [InlineData("// cookbook group: Elsewhere\n", 8, "names cookbook group 'Elsewhere'")]
    public void A_bad_annotation_is_reported_at_its_line(string annotation, int line, string message)
    {
        using var temp = new TempFolder();
        temp.Write("lib.gmac", "// cookbook group 1: Vectors\n" + Library + "\n" + annotation + Macro);
        var (exit, _, err) = Tool.Run("cookbook", "--dsl", temp.Path);
        Assert.Equal(1, exit);
        Assert.Contains($"lib.gmac({line},", err);
        Assert.Contains("error GMAC0005", err);
        Assert.Contains(message, err);
    }

    [Fact]
    public void A_macro_without_a_group_is_reported_and_a_grouped_one_is_written()
    {
        using var temp = new TempFolder();
        temp.Write("lib.gmac", Library + "\n" + Macro);
        var (exit, _, err) = Tool.Run("cookbook", "--dsl", temp.Path);
        Assert.Equal(1, exit);
        Assert.Contains("error GMAC0005: macro 'Swap' has no cookbook group", err);

        temp.Write("lib.gmac", "// cookbook group 1: Vectors\n// Of the plane.\n\n" + Library + "\n// Swaps the coordinates.\n// cookbook hand: (y, x)\n" + Macro);
        (exit, var output, err) = Tool.Run("cookbook", "--dsl", temp.Path);
        Assert.True(exit == 0, err);
        Assert.Contains("## Vectors\n\nOf the plane.\n", output);
        Assert.Contains("Swaps the coordinates.", output);
        Assert.Contains("//GMac.Bind(\"u\", \"V\", u);", output);
        Assert.Contains("By hand: (y, x)", output);
    }

    [Fact]
    public void Check_reports_an_out_of_date_file_with_the_command_to_run()
    {
        using var temp = new TempFolder();
        temp.Write("lib.gmac", "// cookbook group 1: Vectors\n" + Library + "\n" + Macro);
        var file = temp.Write("cookbook.md", "old\n");
        var (exit, _, err) = Tool.Run("cookbook", "--dsl", temp.Path, "-o", file, "--check");
        Assert.Equal(1, exit);
        Assert.Contains("out of date", err);
        Assert.Contains("cookbook --dsl dsl -o docs/cookbook.md", err);
        Assert.Equal(0, Tool.Run("cookbook", "--dsl", temp.Path, "-o", file).Exit);
        Assert.Equal(0, Tool.Run("cookbook", "--dsl", temp.Path, "-o", file, "--check").Exit);
    }

    [Fact]
    public void Help_explains_the_annotations()
    {
        var (exit, output, _) = Tool.Run("cookbook", "--help");
        Assert.Equal(0, exit);
        Assert.Contains("cookbook group N: Title", output);
        Assert.Contains("cookbook bind:", output);
        Assert.Contains("cookbook hand:", output);
    }

    private const string Library = "define frame f as basis: {x, y} Euclidean end frame\n" +
        "define subspace f.vectors as basis {x, y} end subspace\n" +
        "define multivector class f.V as vectors end multivector class\n" +
        "define binding V as use frame f bind { x : <x>; y : <y> } end binding\n";

    private const string Macro = "define macro Swap as inputs: { u : f.V } outputs: { w : f.V } performs: w = f.multivector { x : u.<y>; y : u.<x> }; end macro\n";
}
