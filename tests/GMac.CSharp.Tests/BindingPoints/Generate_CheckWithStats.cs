using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>
/// <c>generate --check</c> takes a region as current whether or not it has the statistics header,
/// so it agrees with <c>generate</c> run with or without <c>--stats</c>.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_CheckWithStats : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    [Theory]
    [InlineData(true, false)]
    [InlineData(false, true)]
    [InlineData(true, true)]
    [InlineData(false, false)]
    public void A_generated_file_checks_current_whatever_the_stats_flags(bool generateStats, bool checkStats)
    {
        var path = _temp.Write("Normals.cs", StaleKernel.Text);
        var (exit, _, err) = Tool.Generate([_temp.Path], stats: generateStats);
        Assert.True(exit == 0, err);
        Assert.Equal(generateStats, File.ReadAllText(path).Contains("// GMac: ", StringComparison.Ordinal));
        var generated = File.ReadAllBytes(path);

        var (checkExit, output, checkErr) = Tool.Generate([_temp.Path], check: true, stats: checkStats);

        Assert.True(checkExit == 0, checkErr);
        Assert.Contains("0 file(s) out of date", output, StringComparison.Ordinal);
        Assert.Equal(generated, File.ReadAllBytes(path));
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void A_stale_region_is_still_reported(bool checkStats)
    {
        var path = _temp.Write("Normals.cs", StaleKernel.Text);

        var (exit, _, err) = Tool.Generate([_temp.Path], check: true, stats: checkStats);

        Assert.Equal(1, exit);
        Assert.Matches(@"Normals\.cs\(8,9\): error GMAC0410", err);
        Assert.Equal(StaleKernel.Text, File.ReadAllText(path));
    }

    [Fact]
    public void A_binding_line_after_the_code_is_out_of_date()
    {
        var path = _temp.Write("Normals.cs", StaleKernel.Text);
        Assert.Equal(0, Tool.Generate([_temp.Path]).Exit);
        var lines = File.ReadAllLines(path).ToList();
        var binding = lines.FindIndex(l => l.Contains("//GMac.Bind(\"w.e3\"", StringComparison.Ordinal));
        var moved = lines[binding];
        lines.RemoveAt(binding);
        lines.Insert(lines.FindIndex(l => l.Trim() == "#endregion"), moved);
        File.WriteAllLines(path, lines);

        var (exit, _, err) = Tool.Generate([_temp.Path], check: true);

        Assert.Equal(1, exit);
        Assert.Contains("GMAC0410", err, StringComparison.Ordinal);
    }
}
