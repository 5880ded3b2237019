using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>
/// A region's body is generated, so a directive in it would be deleted and change how the rest of
/// the file compiles: it is refused where it is, and the file left alone.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_DirectivesInRegions : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    [Theory]
    [InlineData("#nullable enable")]
    [InlineData("#pragma warning disable CS0168")]
    [InlineData("#if DEBUG\n#endif")]
    [InlineData("#define FAST")]
    [InlineData("#warning check this")]
    [InlineData("#line 200")]
    public void A_directive_inside_a_region_is_refused_at_its_line(string directive)
    {
        var text = StaleKernel.Text.Replace("//GMac.Bind(\"v.e1\"", "  " + directive.Replace("\n", "\n  ", StringComparison.Ordinal) + "\n        //GMac.Bind(\"v.e1\"", StringComparison.Ordinal);
        var path = _temp.Write("Normals.cs", text);
        var lines = text.Split('\n');
        var line = Array.FindIndex(lines, l => l.TrimStart().StartsWith(directive.Split('\n')[0], StringComparison.Ordinal)) + 1;
        var column = lines[line - 1].IndexOf('#', StringComparison.Ordinal) + 1;

        var (exit, _, err) = Tool.Generate([path]);

        Assert.Equal(1, exit);
        Assert.Contains($"Normals.cs({line},{column}): error GMAC0430: #{directive[1..].Split(' ', '\n')[0]} inside the GMac region of line ", err, StringComparison.Ordinal);
        Assert.Equal(text, File.ReadAllText(path));
    }
}
