using System.Globalization;
using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.Build;

/// <summary>
/// The packages as a user meets them, in a folder outside the repository: GMac.Build added to a
/// new console project from a local feed fills its binding point at build time from a macro of the
/// user's own over the standard library, the program prints the right numbers, a second build does
/// not generate again, and a broken macro is a build error at its file, line and column. The same
/// macro through the gmac dotnet tool installed from a tool manifest.
/// </summary>
public sealed class Package_NewProject : IClassFixture<Package_NewProject.PackedFeed>, IDisposable
{
    private readonly TempFolder _temp = new();
    private readonly Dictionary<string, string> _environment;
    private readonly string _feed;

    public Package_NewProject(PackedFeed feed)
    {
        _feed = feed.Folder;
        // A private package folder: the packages under test are never served from, or left in, the user's cache.
        _environment = new() { ["NUGET_PACKAGES"] = Path.Combine(_temp.Path, "packages") };
        _temp.Write("nuget.config", $"""
            <?xml version="1.0" encoding="utf-8"?>
            <configuration>
              <packageSources>
                <add key="local" value="{_feed}" />
              </packageSources>
            </configuration>
            """);
        // Empty Directory.Build files stop MSBuild from importing any found above the temp folder.
        _temp.Write("Directory.Build.props", "<Project />\n");
        _temp.Write("Directory.Build.targets", "<Project />\n");
    }

    /// <summary>Both packages, packed once for the class from what this test assembly's build built (its project references).</summary>
    public sealed class PackedFeed : IDisposable
    {
        private readonly TempFolder _temp = new();

        public PackedFeed()
        {
            foreach (var project in new[] { "GMac.Build", "GMac.Cli" })
            {
                var (exit, output) = DotnetCommand.Run(SharedDsl.RepositoryRoot,
                    ["pack", Path.Combine(SharedDsl.RepositoryRoot, "src", project), "-c", DotnetBuild.Configuration, "--no-build", "-o", Folder]);
                if (exit != 0) throw new InvalidOperationException($"dotnet pack {project} failed:\n{output}");
            }
        }

        public string Folder => Path.Combine(_temp.Path, "feed");

        public void Dispose() => _temp.Dispose();
    }

    // Reflection of x in the plane with unit normal n, y = -n x n, is x with its n-component negated.
    private const string Macro = """
        define macro ReflectInPlane as
            inputs: { n : e3d.Vector; x : e3d.Vector }
            outputs: { y : e3d.Vector }
            performs:
                y = -(n gp x gp n);
        end macro
        """;

    private const string Program = """
        using System.Globalization;

        var n = new V(0.6, 0, 0.8);
        var x = new V(1, 2, 3);
        var y = new V(0, 0, 0);
        #region GMac : ReflectInPlane
        //GMac.Bind("n", "Vector3D", "n");
        //GMac.Bind("x", "Vector3D", "x");
        //GMac.Bind("y", "Vector3D", "y");
        #endregion
        Console.WriteLine(string.Join(" ", new[] { y.x, y.y, y.z }.Select(c => c.ToString("R", CultureInfo.InvariantCulture))));

        class V(double x, double y, double z)
        {
            public double x = x, y = y, z = z;
        }
        """;

    [Fact]
    public void Build_package_generates_at_build_time_only_when_inputs_change_and_reports_dsl_errors_at_their_position()
    {
        var project = NewConsole("App");
        Succeeds(project, "add", "package", "GMac.Build");
        var macroFile = Write(project, "Reflect.gmac", Macro);
        var programFile = Write(project, "Program.cs", Program);

        var (exit, output) = Dotnet(project, "build", "-v:normal");
        Assert.True(exit == 0, output);
        Assert.Contains("y.x =", File.ReadAllText(programFile), StringComparison.Ordinal);
        AssertPrintsReflection(Dotnet(project, "run", "--no-build"));

        (exit, output) = Dotnet(project, "build", "-v:normal");
        Assert.True(exit == 0, output);
        Assert.Contains("Skipping target \"GMacGenerate\"", output, StringComparison.Ordinal);

        File.WriteAllText(macroFile, Macro.Replace("y = -(n gp x gp n);", "y = -(n gp x gp n;", StringComparison.Ordinal));
        (exit, output) = Dotnet(project, "build");
        Assert.NotEqual(0, exit);
        Assert.Matches(@"Reflect\.gmac\(5,\d+\): error GMAC\d{4}:", output);
    }

    [Fact]
    public void Tool_from_a_local_manifest_generates_with_the_standard_library()
    {
        var project = NewConsole("ToolApp");
        Write(project, "Reflect.gmac", Macro);
        var programFile = Write(project, "Program.cs", Program);
        Succeeds(project, "new", "tool-manifest");
        Succeeds(project, "tool", "install", "--local", "GMac.Cli", "--add-source", _feed);

        Succeeds(project, "gmac", "generate", "Program.cs", "--dsl", "Reflect.gmac", "--standard-library");
        Assert.Contains("y.x =", File.ReadAllText(programFile), StringComparison.Ordinal);
        Succeeds(project, "build");
        AssertPrintsReflection(Dotnet(project, "run", "--no-build"));
    }

    /// <summary>x − 2 (n·x) n with n = (0.6, 0, 0.8), x = (1, 2, 3): n·x = 3, so y = (−2.6, 2, −1.8).</summary>
    private static void AssertPrintsReflection((int Exit, string Output) run)
    {
        Assert.True(run.Exit == 0, run.Output);
        var values = run.Output.Trim().Split(' ').Select(v => double.Parse(v, CultureInfo.InvariantCulture)).ToArray();
        double[] expected = [-2.6, 2, -1.8];
        Assert.Equal(3, values.Length);
        for (var i = 0; i < 3; i++) Assert.Equal(expected[i], values[i], 12);
    }

    private string NewConsole(string name)
    {
        Succeeds(_temp.Path, "new", "console", "-n", name, "-o", name);
        return Path.Combine(_temp.Path, name);
    }

    private static string Write(string folder, string name, string text)
    {
        var path = Path.Combine(folder, name);
        File.WriteAllText(path, text);
        return path;
    }

    private (int Exit, string Output) Dotnet(string folder, params string[] arguments) => DotnetCommand.Run(folder, arguments, _environment);

    private void Succeeds(string folder, params string[] arguments)
    {
        var (exit, output) = Dotnet(folder, arguments);
        Assert.True(exit == 0, $"dotnet {string.Join(' ', arguments)} failed:\n{output}");
    }

    public void Dispose() => _temp.Dispose();
}
