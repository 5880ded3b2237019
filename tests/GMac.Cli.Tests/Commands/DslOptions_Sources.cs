using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.Commands;

/// <summary>
/// The DSL of a command from several places bound as one project: <c>--dsl</c> folders and
/// <c>.gmac</c> files (repeatable), a <c>--dsl-from</c> list, and <c>--standard-library</c>, the
/// library copied next to gmac.
/// </summary>
public sealed class DslOptions_Sources : IDisposable
{
    private readonly TempFolder _temp = new();

    private const string Frame = """
        define frame f2 as
            basis: {a, b}
            Euclidean
        end frame
        define subspace f2.vectors as basis {a, b} end subspace
        define multivector class f2.V as vectors end multivector class
        """;

    private const string Macro = """
        define macro Twice as
            inputs: { u : f2.V }
            outputs: { w : f2.V }
            performs:
                w = 2 * u;
        end macro
        """;

    [Fact]
    public void Files_named_with_dsl_are_bound_together_and_one_alone_misses_the_other()
    {
        var frame = _temp.Write("frame.gmac", Frame);
        var macro = _temp.Write(Path.Combine("more", "twice.gmac"), Macro);

        var (exit, output, err) = Tool.Run("check", "--dsl", frame, "--dsl", macro);
        Assert.True(exit == 0, err);
        Assert.StartsWith("2 file(s), 1 macro(s)", output, StringComparison.Ordinal);

        (exit, _, err) = Tool.Run("check", "--dsl", macro);
        Assert.Equal(1, exit);
        Assert.Contains("twice.gmac(3,", err, StringComparison.Ordinal);
    }

    [Fact]
    public void A_list_names_folders_and_files_relative_to_itself_and_a_file_reached_twice_is_read_once()
    {
        _temp.Write(Path.Combine("lib", "frame.gmac"), Frame);
        _temp.Write(Path.Combine("lib", "twice.gmac"), Macro);
        var list = _temp.Write(Path.Combine("obj", "dsl.list"), "../lib\n\n../lib/twice.gmac\n");

        var (exit, output, err) = Tool.Run("check", "--dsl-from", list);

        Assert.True(exit == 0, err);
        Assert.StartsWith("2 file(s), 1 macro(s)", output, StringComparison.Ordinal);
    }

    [Fact]
    public void The_standard_library_is_the_repository_dsl_folder_and_user_macros_build_on_it()
    {
        var library = Directory.GetFiles(SharedDsl.DslDirectory, "*.gmac", SearchOption.AllDirectories);
        var macro = _temp.Write("normal.gmac", """
            define macro MyNormal as
                inputs: { u : e3d.Vector; v : e3d.Vector }
                outputs: { w : e3d.Vector }
                performs:
                    w = NormalToVectors(u, v);
            end macro
            """);

        var (exit, output, err) = Tool.Run("check", "--standard-library", "--dsl", macro);

        Assert.True(exit == 0, err);
        Assert.StartsWith($"{library.Length + 1} file(s)", output, StringComparison.Ordinal);
        (exit, output, err) = Tool.Run("show", "MyNormal", "--standard-library", "--dsl", macro);
        Assert.True(exit == 0, err);
        Assert.Contains("w_e1 =", output, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("check")]
    [InlineData("generate", ".")]
    [InlineData("show", "M")]
    [InlineData("verify", ".")]
    public void Without_any_dsl_the_command_line_is_refused_naming_the_three_ways(params string[] args)
    {
        var (exit, output, err) = Tool.Run(args);

        Assert.Equal(2, exit);
        Assert.Equal("", output);
        Assert.Contains("'--dsl' is required (or '--dsl-from', or '--standard-library')", err, StringComparison.Ordinal);
    }

    public void Dispose() => _temp.Dispose();
}
