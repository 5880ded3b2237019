using System.CommandLine;

namespace GMac.Cli.Commands;

/// <summary>The options every command that loads a GMacDSL folder takes, made fresh for each command.</summary>
internal static class SharedOptions
{
    public static Option<string> Dsl() => new("--dsl")
    {
        Description = "the GMacDSL folder (its .gmac files)",
        HelpName = "DIR",
        Required = true,
    };

    public static Option<string?> Cache() => new("--cache")
    {
        Description = "where simplifier answers are cached (default: DIR/.gmac-cache)",
        HelpName = "DIR",
    };

    public static Option<bool> Stats(string what) => new("--stats") { Description = what };

    /// <summary>The scalar type of generated code; a binding point's <c>//GMac.Type</c> line overrides it.</summary>
    public static Option<string> Scalar(string what)
    {
        var option = new Option<string>("--scalar")
        {
            Description = what,
            HelpName = string.Join("|", GMac.Core.CodeGeneration.CSharpEmitOptions.ScalarTypes),
            DefaultValueFactory = _ => "double",
        };
        option.AcceptOnlyFromAmong([.. GMac.Core.CodeGeneration.CSharpEmitOptions.ScalarTypes]);
        return option;
    }

    /// <summary>The C# files or folders to work on; none means the current folder.</summary>
    public static Argument<string[]> Paths(string what) => new("PATH")
    {
        Description = what + " (default: .)",
        Arity = ArgumentArity.ZeroOrMore,
    };

    public static IReadOnlyList<string> PathsOrCurrent(string[]? paths) => paths is { Length: > 0 } ? paths : ["."];
}
