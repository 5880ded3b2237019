using System.Text.RegularExpressions;
using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.Commands;

/// <summary>Every diagnostic <c>gmac show</c> prints has the form <c>path(line,col): error GMACxxxx: message</c>.</summary>
public sealed class ShowCommand_Positions
{
    private const string Dsl = """
        define frame e3d as basis: {e1, e2, e3} Euclidean end frame
        define subspace e3d.vectors as basis {e1, e2, e3} end subspace
        define subspace e3d.scalars as basis {1} end subspace
        define multivector class e3d.Vector as vectors end multivector class
        define multivector class e3d.Scalar as scalars end multivector class
        define macro DivZero as
            inputs: { x : e3d.Vector }
            outputs: { w : e3d.Vector }
            performs:
                w = x / (x.<e1> - x.<e1>);
        end macro
        define macro Norm2 as
            inputs: { u : e3d.Vector }
            outputs: { s : e3d.Scalar }
            performs:
                s = (u sp u).<1>;
        end macro
        """;

    private static readonly Regex Positioned = new(@"^(?<path>.+\.gmac)\((?<line>\d+),(?<col>\d+)\): error (?<code>GMAC\d{4}): ");

    private static (int Exit, Match[] Lines) Show(params string[] args)
    {
        using var temp = new TempFolder();
        temp.Write("a.gmac", Dsl);
        var (exit, _, err) = Tool.Run(["show", .. args, "--dsl", temp.Path, "--cache", Path.Combine(temp.Path, "cache")]);
        var lines = err.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);
        Assert.NotEmpty(lines);
        var matches = lines.Select(l => Positioned.Match(l)).ToArray();
        Assert.True(matches.All(m => m.Success), $"unpositioned diagnostic in:\n{err}");
        return (exit, matches);
    }

    [Fact]
    public void Division_by_a_symbolic_zero_is_reported_at_the_division()
    {
        var (exit, lines) = Show("DivZero");
        Assert.Equal(1, exit);
        var line = Assert.Single(lines);
        Assert.Equal(("GMAC0313", "10", "13"), (line.Groups["code"].Value, line.Groups["line"].Value, line.Groups["col"].Value));
    }

    [Fact]
    public void Empty_bounds_from_min_and_max_options_are_reported_with_the_option()
    {
        var (exit, lines) = Show("Norm2", "--bind", "u.e1=<a>", "--bind", "s.1=<r>", "--min", "a=3", "--max", "a=1");
        Assert.Equal(1, exit);
        var line = Assert.Single(lines);
        Assert.Equal("GMAC0312", line.Groups["code"].Value);
        Assert.Equal("12", line.Groups["line"].Value); // the macro's declaration
    }

    [Fact]
    public void A_bind_option_naming_no_parameter_is_positioned_at_the_macro()
    {
        var (exit, lines) = Show("Norm2", "--bind", "q.e1=<a>", "--bind", "s.1=<r>");
        Assert.Equal(1, exit);
        Assert.Contains(lines, l => l.Groups["code"].Value == "GMAC0302" && l.Groups["line"].Value == "12");
    }

    [Fact]
    public void An_unknown_macro_is_positioned_in_the_dsl_folder()
    {
        using var temp = new TempFolder();
        temp.Write("a.gmac", Dsl);
        var (exit, _, err) = Tool.Run("show", "Nope", "--dsl", temp.Path, "--cache", Path.Combine(temp.Path, "cache"));
        Assert.Equal(1, exit);
        Assert.StartsWith($"{temp.Path}(1,1): error GMAC0301: ", err);
    }

    [Fact]
    public void Check_rejects_a_constant_without_a_real_value()
    {
        using var temp = new TempFolder();
        temp.Write("a.gmac", Dsl + "\ndefine constant e3d.Bad as multivector { e1 : sqrt(-4) } end constant\n");
        var (exit, _, err) = Tool.Run("check", "--dsl", temp.Path);
        Assert.Equal(1, exit);
        Assert.Matches(@"a\.gmac\(18,47\): error GMAC0132: ", err);
    }
}
