using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.Commands;

/// <summary>
/// The command-line syntax of every command: generated help, <c>--name=value</c> as well as
/// <c>--name value</c>, and usage errors (exit 2) that name what was wrong.
/// </summary>
public sealed class CommandLine_Syntax
{
    [Theory]
    [InlineData("generate", "--dsl", "--sources-from", "--check", "--stats", "--cache")]
    [InlineData("check", "--dsl", "--timing")]
    [InlineData("show", "--dsl", "--bind", "--min", "--max", "--stats", "--cache")]
    [InlineData("verify", "--dsl", "--seed", "--cache")]
    public void Help_of_each_command_exits_0_and_lists_its_options(string command, params string[] options)
    {
        foreach (var help in new[] { "--help", "-h" })
        {
            var (exit, output, err) = Tool.Run(command, help);
            Assert.True(exit == 0, err);
            Assert.Matches($@"Usage:\s+\S+ {command}\b", output);
            foreach (var option in options) Assert.Matches($@"(?m)^\s+{option}\b", output);
        }
    }

    [Fact]
    public void Root_help_exits_0_and_lists_the_commands_with_their_summaries()
    {
        foreach (var help in new[] { "--help", "help" })
        {
            var (exit, output, _) = Tool.Run(help);
            Assert.Equal(0, exit);
            Assert.Contains("Rewrite the binding points", output);
            Assert.Contains("Print the code generated for one macro", output);
        }
    }

    [Fact]
    public void Options_take_their_value_after_an_equals_sign()
    {
        using var temp = new TempFolder();
        var file = temp.Write("Normals.cs", StaleKernel.Text);
        var (exit, output, err) = Tool.Run("generate", file, $"--dsl={SharedDsl.DslDirectory}", $"--cache={Path.Combine(temp.Path, "cache")}");
        Assert.True(exit == 0, err);
        Assert.Contains("1 file(s) changed", output);
        var text = File.ReadAllText(file);
        Assert.DoesNotContain(StaleKernel.StaleLine, text);
        Assert.Contains(StaleKernel.GeneratedMarker, text);
    }

    [Theory]
    [InlineData("--frobnicate", "check", "--dsl", "x", "--frobnicate")]
    [InlineData("--frobnicate=1", "generate", "--dsl", "x", "--frobnicate=1")]
    [InlineData("--sed", "verify", "--dsl", "x", "--sed", "3")]
    public void Unknown_option_exits_2_and_is_named(string named, params string[] args)
    {
        var (exit, output, err) = Tool.Run(args);
        Assert.Equal(2, exit);
        Assert.Contains($"'{named}'", err);
        Assert.Equal("", output);
    }

    [Theory]
    [InlineData("genrate", "generate", "genrate", "--dsl", "x")]
    [InlineData("--dls", "--dsl", "check", "--dls", "x")]
    [InlineData("--dls", "--dsl", "verify", "--dls", "x")]
    [InlineData("--sed", "--seed", "verify", "--dsl", "x", "--sed", "3")]
    [InlineData("--bnd", "--bind", "show", "M", "--dsl", "x", "--bnd", "u=V:a")]
    public void Mistyped_names_get_a_suggestion(string typo, string meant, params string[] args)
    {
        var (exit, _, err) = Tool.Run(args);
        Assert.Equal(2, exit);
        Assert.Matches($@"'{typo}'[^\n]*\. Did you mean[^\n]*\n?\s*'?{meant}\b", err);
    }

    [Theory]
    [InlineData("'--dsl'", "check")]
    [InlineData("'--dsl'", "generate", ".")]
    [InlineData("'--dsl'", "show", "M")]
    [InlineData("'show'", "show", "--dsl", "x")]
    [InlineData("'--dsl'", "check", "--dsl")]
    public void Missing_required_argument_exits_2_and_says_which(string named, params string[] args)
    {
        var (exit, output, err) = Tool.Run(args);
        Assert.Equal(2, exit);
        Assert.Contains(named, err);
        Assert.Equal("", output);
    }

    /// <summary>FILE and DSL stand for a stale C# file and the DSL folder.</summary>
    [Theory]
    [InlineData("'--cache'", "generate", "FILE", "--dsl", "DSL", "--cache", "")]
    [InlineData("'--cache'", "verify", "FILE", "--dsl", "DSL", "--cache", " ")]
    [InlineData("'--cache'", "show", "NormalToVectors", "--dsl", "DSL", "--cache", "")]
    [InlineData("'--dsl'", "generate", "FILE", "--dsl", "")]
    [InlineData("'--dsl'", "check", "--dsl", "")]
    [InlineData("PATH", "generate", "", "--dsl", "DSL")]
    [InlineData("PATH", "generate", "FILE", " ", "--dsl", "DSL")]
    public void An_empty_value_exits_2_naming_it_before_any_file_is_touched(string named, params string[] args)
    {
        using var temp = new TempFolder();
        var file = temp.Write("Normals.cs", StaleKernel.Text);
        args = [.. args.Select(a => a switch { "FILE" => file, "DSL" => SharedDsl.DslDirectory, _ => a })];

        var (exit, output, err) = Tool.Run(args);

        Assert.Equal(2, exit);
        Assert.Matches($"{System.Text.RegularExpressions.Regex.Escape(named)}[^\n]* empty", err);
        Assert.DoesNotContain(": error", err);
        Assert.Equal("", output);
        Assert.Equal(StaleKernel.Text, File.ReadAllText(file));
    }

    [Theory]
    [InlineData("--bind", "nonsense")]
    [InlineData("--bind", "u.=x")]
    [InlineData("--min", "cr=zero")]
    [InlineData("--max", "=1")]
    public void Unreadable_binding_option_exits_2_and_quotes_it(string option, string value)
    {
        var (exit, _, err) = Tool.Run("show", "M", "--dsl", "x", option, value);
        Assert.Equal(2, exit);
        Assert.Contains($"cannot read '{option} {value}'", err);
    }
}
