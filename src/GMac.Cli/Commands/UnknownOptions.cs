using System.CommandLine;

namespace GMac.Cli.Commands;

/// <summary>
/// System.CommandLine hands a token such as <c>--sed</c> to an argument that can still take a
/// value (a PATH list, a MACRO) instead of calling it unknown. gmac never takes a <c>--</c> token
/// as a path or a macro name, so it is reported as an unknown option, with the nearest option names.
/// </summary>
internal static class UnknownOptions
{
    public static void RejectIn<T>(Argument<T> argument, Command command) =>
        argument.Validators.Add(result =>
        {
            foreach (var token in result.Tokens.Where(t => t.Value.StartsWith("--", StringComparison.Ordinal)))
                result.AddError(Message(token.Value, command));
        });

    private static string Message(string token, Command command)
    {
        var name = token.Split('=', 2)[0];
        var near = command.Options.Select(o => o.Name).Where(o => Distance(o, name) <= 2).Select(o => $"'{o}'").ToList();
        return $"Unrecognized option '{token}'." + (near.Count > 0 ? $" Did you mean {string.Join(" or ", near)}?" : "");
    }

    /// <summary>Edit distance (insertions, deletions, substitutions) between two short names.</summary>
    private static int Distance(string a, string b)
    {
        var row = Enumerable.Range(0, b.Length + 1).ToArray();
        for (var i = 1; i <= a.Length; i++)
        {
            var diagonal = row[0];
            row[0] = i;
            for (var j = 1; j <= b.Length; j++)
            {
                var above = row[j];
                row[j] = Math.Min(Math.Min(row[j] + 1, row[j - 1] + 1), diagonal + (a[i - 1] == b[j - 1] ? 0 : 1));
                diagonal = above;
            }
        }
        return row[b.Length];
    }
}
