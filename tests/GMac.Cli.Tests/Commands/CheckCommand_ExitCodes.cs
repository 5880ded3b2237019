using GMac.Cli.Commands;

namespace GMac.Cli.Tests.Commands;

/// <summary><c>gmac check</c>: exit codes, MSBuild-format diagnostics on standard error.</summary>
public sealed class CheckCommand_ExitCodes : IDisposable
{
    private readonly string _temp = Directory.CreateTempSubdirectory("gmac-check-").FullName;

    public void Dispose() => Directory.Delete(_temp, recursive: true);

    private static (int Exit, string Out, string Err) Run(params string[] args)
    {
        var output = new StringWriter();
        var error = new StringWriter();
        var exit = CommandLine.Run(args, output, error);
        return (exit, output.ToString(), error.ToString());
    }

    private static string DslLibrary
    {
        get
        {
            var dir = new DirectoryInfo(AppContext.BaseDirectory);
            while (dir is not null && !File.Exists(Path.Combine(dir.FullName, "GMac.sln"))) dir = dir.Parent;
            return Path.Combine(dir!.FullName, "dsl");
        }
    }

    [Fact]
    public void Library_checks_clean_with_exit_0()
    {
        var (exit, _, err) = Run("check", "--dsl", DslLibrary);
        Assert.True(exit == 0, err);
        Assert.DoesNotContain(": error ", err);
    }

    [Fact]
    public void A_gmac_file_is_read_alone_and_any_other_file_is_called_a_file()
    {
        var frames = Path.Combine(DslLibrary, "frames.gmac");
        var (exit, output, _) = Run("check", "--dsl", frames);
        Assert.Equal(0, exit);
        Assert.StartsWith("1 file(s)", output, StringComparison.Ordinal);

        var readme = Path.Combine(DslLibrary, "README.md");
        (exit, _, var err) = Run("check", "--dsl", readme);
        Assert.Equal(1, exit);
        Assert.Contains($"{readme}(1,1): error GMAC0003: '{readme}' is a file, not a DSL folder or a .gmac file: name the folder that holds the .gmac files (here '{DslLibrary}')", err);
    }

    [Fact]
    public void Errors_go_to_stderr_in_msbuild_format_with_exit_1()
    {
        File.WriteAllText(Path.Combine(_temp, "bad.gmac"), "define frame a as basis: {x} Euclidean end frame\ndefine frame a as basis: {x} Euclidean end frame\n");
        var (exit, _, err) = Run("check", "--dsl", _temp);
        Assert.Equal(1, exit);
        Assert.Matches(@"bad\.gmac\(2,14\): error GMAC0102: frame 'a' is already defined", err);
    }

    [Fact]
    public void Warnings_alone_still_exit_0()
    {
        File.WriteAllText(Path.Combine(_temp, "warn.gmac"), """
            define frame a as basis: {x} Euclidean end frame
            define constant a.K as multivector { x : 1 } end constant
            """);
        var (exit, _, err) = Run("check", "--dsl", _temp);
        Assert.Equal(0, exit);
        Assert.Contains("warning GMAC0201", err);
    }

    [Fact]
    public void Missing_folder_is_a_diagnostic_with_exit_1()
    {
        var (exit, _, err) = Run("check", "--dsl", Path.Combine(_temp, "nope"));
        Assert.Equal(1, exit);
        Assert.Contains("error GMAC0003", err);
    }

    [Theory]
    [InlineData]
    [InlineData("frobnicate")]
    [InlineData("check")]
    [InlineData("check", "--dsl")]
    [InlineData("check", "--dsl", "x", "--bogus")]
    public void Usage_errors_exit_2(params string[] args)
    {
        var (exit, _, err) = Run(args);
        Assert.Equal(2, exit);
        Assert.Matches(@"Usage:\s+\S+ ", err);
    }

    [Fact]
    public void Help_exits_0_and_lists_check()
    {
        var (exit, output, _) = Run("--help");
        Assert.Equal(0, exit);
        Assert.Contains("check", output);
    }

    [Fact]
    public void Timing_flag_reports_milliseconds()
    {
        var (exit, output, _) = Run("check", "--dsl", DslLibrary, "--timing");
        Assert.Equal(0, exit);
        Assert.Matches(@"parse\+bind \(warm, median of 20\): \d+\.\d ms", output);
    }
}
