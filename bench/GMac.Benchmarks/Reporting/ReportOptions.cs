namespace GMac.Benchmarks.Reporting;

/// <summary>Options of the <c>report</c> command.</summary>
public sealed record ReportOptions(bool Quick, string OutputDirectory, string DslDirectory, bool SkipGeneration)
{
    /// <summary><c>--vector-only</c>: times only the vector section and prints it, writing no file.</summary>
    public bool VectorOnly { get; init; }

    public const string Usage = "usage: GMac.Benchmarks report [--quick] [--out DIR] [--dsl DIR] [--no-generation] [--vector-only]";

    /// <summary>Parses the arguments after <c>report</c>; null and a message on a usage error.</summary>
    public static ReportOptions? Parse(IReadOnlyList<string> args, out string? error)
    {
        error = null;
        var quick = false;
        var skip = false;
        var vectorOnly = false;
        string? output = null, dsl = null;
        for (var i = 0; i < args.Count; i++)
        {
            switch (args[i])
            {
                case "--quick": quick = true; break;
                case "--no-generation": skip = true; break;
                case "--vector-only": vectorOnly = true; break;
                case "--out" or "--dsl" when i + 1 < args.Count:
                    if (args[i] == "--out") output = args[++i];
                    else dsl = args[++i];
                    break;
                case "--out" or "--dsl":
                    error = $"{args[i]} needs a folder";
                    return null;
                default:
                    error = $"unknown argument '{args[i]}'";
                    return null;
            }
        }
        var root = RepositoryRoot();
        if (output is null && root is null || dsl is null && root is null)
        {
            error = "cannot find the repository (GMac.sln) above the current folder; pass --out and --dsl";
            return null;
        }
        return new ReportOptions(quick, output ?? Path.Combine(root!, "bench", "results"), dsl ?? Path.Combine(root!, "dsl"), skip) { VectorOnly = vectorOnly };
    }

    private static string? RepositoryRoot()
    {
        foreach (var start in new[] { Directory.GetCurrentDirectory(), AppContext.BaseDirectory })
        {
            for (var dir = new DirectoryInfo(start); dir is not null; dir = dir.Parent)
                if (File.Exists(Path.Combine(dir.FullName, "GMac.sln")) && Directory.Exists(Path.Combine(dir.FullName, "dsl")))
                    return dir.FullName;
        }
        return null;
    }
}
