using System.CommandLine;

namespace GMac.Cli.Commands;

/// <summary>The options every command that loads a GMacDSL folder takes, made fresh for each command.</summary>
internal static class SharedOptions
{
    public static Option<string?> Cache() => NotBlank(new Option<string?>("--cache")
    {
        Description = "where simplifier answers are cached (default: .gmac-cache in the first --dsl folder, or beside the first --dsl file)",
        HelpName = "DIR",
    });

    public static Option<bool> Stats(string what) => new("--stats") { Description = what };

    /// <summary>
    /// The scalar type of generated code; a binding point's <c>//GMac.Type</c> line overrides it.
    /// The name is taken in any case (<c>Float</c>, <c>vector256&lt;double&gt;</c>), as MSBuild compares property values.
    /// </summary>
    public static Option<string> Scalar(string what)
    {
        var types = GMac.CSharp.Emit.CSharpEmitter.ScalarTypes;
        var option = new Option<string>("--scalar")
        {
            Description = what,
            HelpName = string.Join("|", types),
            DefaultValueFactory = _ => "double",
            CustomParser = result =>
            {
                // no value at all is already an arity error of the parser
                if (result.Tokens.Count == 0) return null;
                var value = result.Tokens[^1].Value;
                if (GMac.CSharp.Emit.CSharpEmitter.ScalarTypeNamed(value) is { } name) return name;
                result.AddError($"--scalar is '{value}'; it must be {string.Join(" or ", types)}.");
                return null;
            },
        };
        option.CompletionSources.Add([.. types]);
        return option;
    }

    /// <summary>Fused multiply–add contraction of generated code; a binding point's <c>//GMac.Fma</c> line overrides it.</summary>
    public static Option<bool> Fma(string what) => new("--fma") { Description = what };

    /// <summary>The C# files or folders to work on; none means the current folder.</summary>
    public static Argument<string[]> Paths(string what)
    {
        var paths = new Argument<string[]>("PATH")
        {
            Description = what + " (default: .)",
            Arity = ArgumentArity.ZeroOrMore,
        };
        paths.Validators.Add(result =>
        {
            if (result.Tokens.Any(t => string.IsNullOrWhiteSpace(t.Value)))
                result.AddError("A PATH is empty: name a C# file or folder (or none, for the current folder).");
        });
        return paths;
    }

    /// <summary>
    /// An empty or blank value (<c>--cache ""</c>, from an unset variable, say) is a usage error,
    /// not a path: it would name no file, or the current folder by accident.
    /// </summary>
    public static Option<T> NotBlank<T>(Option<T> option, string what = "a folder")
    {
        option.Validators.Add(result =>
        {
            if (result.Tokens.Any(t => string.IsNullOrWhiteSpace(t.Value)))
                result.AddError($"The value of '{option.Name}' is empty: it must name {what}.");
        });
        return option;
    }

    public static IReadOnlyList<string> PathsOrCurrent(string[]? paths) => paths is { Length: > 0 } ? paths : ["."];
}
