namespace GMac.Cli.Commands;

/// <summary>
/// The options shared by the commands that work on binding points: paths, <c>--dsl</c>,
/// <c>--cache</c> and flags; anything unknown is a usage error.
/// </summary>
internal sealed class CommandOptions
{
    public List<string> Positional { get; } = [];
    public string? Dsl { get; private set; }
    public string? Cache { get; private set; }
    public HashSet<string> Flags { get; } = new(StringComparer.Ordinal);
    public List<(string Option, string Value)> Values { get; } = [];

    /// <summary>Parses <paramref name="args"/>; returns an error message or null.</summary>
    public static string? TryParse(IReadOnlyList<string> args, IReadOnlySet<string> flags, IReadOnlySet<string> valued, out CommandOptions options)
    {
        options = new CommandOptions();
        for (var i = 0; i < args.Count; i++)
        {
            var a = args[i];
            if (a is "--dsl" or "--cache" || valued.Contains(a))
            {
                if (i + 1 >= args.Count) return $"option '{a}' needs a value";
                var value = args[++i];
                if (a == "--dsl") options.Dsl = value;
                else if (a == "--cache") options.Cache = value;
                else options.Values.Add((a, value));
            }
            else if (flags.Contains(a)) options.Flags.Add(a);
            else if (a.StartsWith("--", StringComparison.Ordinal)) return $"unknown option '{a}'";
            else options.Positional.Add(a);
        }
        return options.Dsl is null ? "missing --dsl DIR" : null;
    }
}
