using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.BindingPoints;

/// <summary>
/// <c>generate --sources-from FILE</c> (how the MSBuild step hands over a project's Compile items):
/// exactly the listed files are generated, wherever they are, relative paths are taken from the
/// list's folder, and a list that cannot be read is an error naming it.
/// </summary>
public sealed class Generate_SourceList : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private string Cache => Path.Combine(_temp.Path, "cache");

    private static bool IsGenerated(string path) => !File.ReadAllText(path).Contains(StaleKernel.StaleLine, StringComparison.Ordinal);

    [Fact]
    public void Exactly_the_listed_files_are_generated()
    {
        var listed = _temp.Write(Path.Combine("project", "Listed.cs"), StaleKernel.Text);
        var beside = _temp.Write(Path.Combine("project", "Beside.cs"), StaleKernel.Text);
        var linked = _temp.Write(Path.Combine("shared", "Linked.cs"), StaleKernel.Text);
        // Blank lines are skipped; the relative path is from the list's folder, not gmac's.
        var list = _temp.Write(Path.Combine("project", "obj", "sources.txt"), $"../Listed.cs\n\n{linked}\n");

        var (exit, output, err) = Tool.Run("generate", "--sources-from", list, "--dsl", SharedDsl.DslDirectory, "--cache", Cache);

        Assert.True(exit == 0, err);
        Assert.Contains("2 file(s) scanned", output);
        Assert.True(IsGenerated(listed));
        Assert.True(IsGenerated(linked));
        Assert.False(IsGenerated(beside));
    }

    [Fact]
    public void A_list_that_cannot_be_read_is_an_error_naming_it()
    {
        var missing = Path.Combine(_temp.Path, "missing.txt");
        var (exit, _, err) = Tool.Run("generate", "--sources-from", missing, "--dsl", SharedDsl.DslDirectory, "--cache", Cache);
        Assert.Equal(1, exit);
        Assert.Contains($"{missing}(1,1): error GMAC0407: cannot read the list of source files", err);
    }
}
