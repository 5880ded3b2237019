using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>
/// Only C# sources are generated, whether found in a folder or named on the command line: a shell
/// expanding <c>gmac generate *</c> also names the README, whose regions are documentation.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_OnlyCSharpSources : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    [Fact]
    public void A_named_file_that_is_not_a_cs_file_is_skipped_with_a_warning()
    {
        // documentation showing a binding point, as the README of a project would
        var doc = _temp.Write("DOC.md", StaleKernel.Text);
        var notes = _temp.Write("Normals.cs.txt", StaleKernel.Text);
        var code = _temp.Write("Normals.cs", StaleKernel.Text);

        // what 'gmac generate *' passes
        var (exit, output, err) = Tool.Generate([doc, code, notes]);

        Assert.True(exit == 0, err);
        Assert.Equal(StaleKernel.Text, File.ReadAllText(doc));
        Assert.Equal(StaleKernel.Text, File.ReadAllText(notes));
        Assert.Contains(StaleKernel.GeneratedMarker, File.ReadAllText(code), StringComparison.Ordinal);
        Assert.Matches(@"DOC\.md\(1,1\): warning GMAC0411: not a C# source file \(only \.cs files are generated\); skipped", err);
        Assert.Matches(@"Normals\.cs\.txt\(1,1\): warning GMAC0411: not a C# source file", err);
        Assert.Contains("1 file(s) scanned", output, StringComparison.Ordinal);
    }
}
