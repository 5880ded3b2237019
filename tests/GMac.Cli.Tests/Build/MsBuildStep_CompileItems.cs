namespace GMac.Cli.Tests.Build;

/// <summary>
/// build/GMac.Build.targets generates exactly the project's <c>Compile</c> items, not the files of its
/// folder: a file linked from outside the folder is generated, and a file of the folder that the
/// project removes from <c>Compile</c> is left alone, even if its binding point is broken.
/// </summary>
public sealed class MsBuildStep_CompileItems
{
    // A stale region (w = u + v, not zero) in a class of its own, for the linked file.
    private const string Shared = """
        namespace Sample;

        public static class Shared
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

    // Not compiled: it binds an output the macro does not have, which generation would report.
    private const string Legacy = """
        namespace Sample.Legacy;

        public static class Old
        {
            public static void Sum(double ax)
            {
                #region GMac : Sum
                //GMac.Bind("q.e1", "<ax>");
                #endregion
            }
        }

        """;

    private const string Kernels = """
        namespace Sample;

        public static class Kernels
        {
            public static double Twice(double a) => 2 * a;
        }

        """;

    [Fact]
    public void Build_generates_a_linked_file_and_leaves_a_removed_one_alone()
    {
        using var project = new SampleProject(Kernels, extraItems: """
            <Compile Include="../Shared/S.cs" Link="Shared/S.cs" />
            <Compile Remove="Legacy/**" />
            """);
        var shared = project.Write(Path.Combine("..", "Shared", "S.cs"), Shared);
        var legacy = project.Write(Path.Combine("Legacy", "Old.cs"), Legacy);

        var (exit, output) = project.Build(restore: true);

        Assert.True(exit == 0, output);
        var generated = File.ReadAllText(shared);
        Assert.Contains("x = ax + bx;", generated);
        Assert.Contains("y = ay + by;", generated);
        Assert.Contains("z = az + bz;", generated);
        Assert.DoesNotContain("x = 0;", generated);
        Assert.Equal(Legacy, File.ReadAllText(legacy));
    }
}
