using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.Commands;

/// <summary><c>gmac show</c>, help and usage errors of the commands that load the DSL themselves.</summary>
public sealed class ShowAndHelp_Commands
{
    private static string Dsl => SharedDsl.DslDirectory;

    [Fact]
    public void Help_lists_every_command()
    {
        var (exit, output, _) = Tool.Run("--help");
        Assert.Equal(0, exit);
        foreach (var command in new[] { "generate", "check", "show", "verify" }) Assert.Contains($"  {command}", output);
    }

    [Theory]
    [InlineData("generate")]
    [InlineData("show")]
    [InlineData("verify")]
    public void Command_help_prints_its_usage(string command)
    {
        var (exit, output, _) = Tool.Run(command, "--help");
        Assert.Equal(0, exit);
        Assert.Matches($@"Usage:\s+\S+ {command} ", output);
    }

    [Theory]
    [InlineData("generate", ".")]
    [InlineData("generate", ".", "--dsl")]
    [InlineData("generate", "--dsl", "x", "--frobnicate")]
    [InlineData("show", "--dsl", "x")]
    [InlineData("show", "A", "B", "--dsl", "x")]
    [InlineData("show", "A", "--dsl", "x", "--bind", "nonsense")]
    [InlineData("verify", "--dsl", "x", "--seed", "many")]
    public void Usage_errors_exit_2(params string[] args)
    {
        var (exit, _, err) = Tool.Run(args);
        Assert.Equal(2, exit);
        Assert.Matches(@"Usage:\s+\S+ ", err);
    }

    [Fact]
    public void Show_with_bindings_prints_the_cross_product_and_stats()
    {
        var (exit, output, err) = Tool.Run("show", "NormalToVectors", "--dsl", Dsl, "--stats",
            "--bind", "u=Vector3D:a", "--bind", "v=Vector3D:b", "--bind", "w.e1=<n.x>", "--bind", "w.e2=<n.y>", "--bind", "w.e3=<n.z>");
        Assert.True(exit == 0, err);
        Assert.Contains("// GMac: 3 additions/subtractions, 6 multiplications", output);
        Assert.Matches(@"n\.x = a\.y \* b\.z - a\.z \* b\.y;|n\.x = -\(a\.z \* b\.y\) \+ a\.y \* b\.z;", output);
    }

    [Fact]
    public void Show_without_bindings_uses_default_names()
    {
        var (exit, output, err) = Tool.Run("show", "NormalToVectors", "--dsl", Dsl);
        Assert.True(exit == 0, err);
        Assert.Contains("w_e1 = ", output);
        Assert.Contains("u_e2", output);
    }

    [Fact]
    public void Show_of_an_unknown_macro_exits_1()
    {
        var (exit, _, err) = Tool.Run("show", "NoSuchMacro", "--dsl", Dsl);
        Assert.Equal(1, exit);
        Assert.Contains("error GMAC0301", err);
    }

    [Fact]
    public void Generate_with_a_broken_dsl_prints_its_diagnostics_and_exits_1()
    {
        using var temp = new TempFolder();
        temp.Write("bad.gmac", "define frame a as basis: {x} Euclidean end frame\ndefine frame a as basis: {x} Euclidean end frame\n");
        var (exit, _, err) = Tool.Run("generate", temp.Path, "--dsl", temp.Path);
        Assert.Equal(1, exit);
        Assert.Contains("error GMAC0102", err);
    }
}
