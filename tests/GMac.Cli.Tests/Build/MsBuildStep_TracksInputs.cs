using System.Text.RegularExpressions;

namespace GMac.Cli.Tests.Build;

/// <summary>
/// build/GMac.Build.targets on a real <c>dotnet build</c> of a small project: it rewrites a stale region,
/// turns a bad binding point into a build error at its line, skips generation when nothing changed,
/// and notices a deleted DSL file (timestamps alone cannot: every remaining input is older than the stamp).
/// </summary>
public sealed class MsBuildStep_TracksInputs
{
    private const string GoodBind = """//GMac.Bind("v.e2", "<by>");""";
    private const string BadBind = """//GMac.Bind("q.e2", "<by>");""";

    // The region's body is stale: w = u + v, not zero.
    private const string Kernels = """
        namespace Sample;

        public static class Kernels
        {
            public static (double X, double Y, double Z) Sum(double ax, double ay, double az, double bx, double by, double bz)
            {
                double x, y, z;

                #region GMac : Sum
                //GMac.Bind("u.e1", "<ax>");
                //GMac.Bind("u.e2", "<ay>");
                //GMac.Bind("u.e3", "<az>");
                //GMac.Bind("v.e1", "<bx>");
                //GMac.Bind("v.e2", "<by>");
                //GMac.Bind("v.e3", "<bz>");
                //GMac.Bind("w.e1", "<x>");
                //GMac.Bind("w.e2", "<y>");
                //GMac.Bind("w.e3", "<z>");
                x = 0;
                y = 0;
                z = 0;
                #endregion

                return (x, y, z);
            }
        }

        """;

    [Fact]
    public void Build_regenerates_reports_skips_and_notices_a_deleted_macro()
    {
        using var project = new SampleProject(Kernels);

        // A stale region is rewritten before the compile.
        var (exit, output) = project.Build(restore: true);
        Assert.True(exit == 0, output);
        var generated = File.ReadAllText(project.KernelsFile);
        Assert.Contains("x = ax + bx;", generated);
        Assert.Contains("y = ay + by;", generated);
        Assert.Contains("z = az + bz;", generated);
        Assert.DoesNotContain("x = 0;", generated);

        // A bad binding point fails the build at its own line and column; the file is left as it was.
        var bad = generated.Replace(GoodBind, BadBind);
        File.WriteAllText(project.KernelsFile, bad);
        var (line, column) = Position(bad, BadBind);
        (exit, output) = project.Build();
        Assert.NotEqual(0, exit);
        Assert.Matches($@"{Regex.Escape(project.KernelsFile)}\({line},{column}\): error GMAC\d{{4}}: ", output);
        Assert.Equal(bad, File.ReadAllText(project.KernelsFile));

        // Fixed, it builds; built again with no change, generation is skipped (the stamp is not touched).
        File.WriteAllText(project.KernelsFile, generated);
        (exit, output) = project.Build();
        Assert.True(exit == 0, output);
        var stampTime = File.GetLastWriteTimeUtc(project.StampFile);
        (exit, output) = project.Build();
        Assert.True(exit == 0, output);
        Assert.Equal(stampTime, File.GetLastWriteTimeUtc(project.StampFile));
        Assert.Equal(generated, File.ReadAllText(project.KernelsFile));

        // Without the DSL file that defines the macro, the next build fails as `gmac generate --check` would.
        File.Delete(project.MacroFile);
        (exit, output) = project.Build();
        Assert.NotEqual(0, exit);
        var (regionLine, _) = Position(generated, "#region GMac : Sum");
        Assert.Matches($@"{Regex.Escape(project.KernelsFile)}\({regionLine},\d+\): error GMAC0301: ", output);
    }

    /// <summary>The 1-based line and column of <paramref name="fragment"/> in <paramref name="text"/>.</summary>
    private static (int Line, int Column) Position(string text, string fragment)
    {
        var lines = text.Split('\n');
        var index = Array.FindIndex(lines, l => l.Contains(fragment, StringComparison.Ordinal));
        Assert.True(index >= 0, $"'{fragment}' not found");
        return (index + 1, lines[index].IndexOf(fragment, StringComparison.Ordinal) + 1);
    }
}
