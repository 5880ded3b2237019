using System.CommandLine;
using System.Diagnostics;
using GMac.CSharp.BindingPoints;

namespace GMac.Cli.Commands;

/// <summary>
/// <c>gmac generate [PATH…] [--sources-from FILE] --dsl DIR|FILE… [--dsl-from FILE] [--standard-library] [--check] [--stats] [--cache DIR] [--scalar TYPE] [--fma]</c>:
/// rewrites every binding point under the paths and in the listed files; with <c>--check</c> only
/// reports files that are out of date.
/// </summary>
internal static class GenerateCommand
{
    public static Command Create()
    {
        var paths = SharedOptions.Paths("C# files or folders whose binding points are rewritten");
        var sourcesFrom = new Option<string?>("--sources-from")
        {
            Description = "also rewrite the C# files listed in FILE, one path a line, relative to FILE's folder (with it, no PATH means none)",
            HelpName = "FILE",
        };
        sourcesFrom.Validators.Add(result =>
        {
            if (result.Tokens.Any(t => string.IsNullOrWhiteSpace(t.Value))) result.AddError("--sources-from needs the path of a file listing C# files");
        });
        var dsl = new DslOptions();
        var check = new Option<bool>("--check") { Description = "write nothing; exit 1 if any region is out of date" };
        var stats = SharedOptions.Stats("begin each region with a comment counting its operations");
        var cache = SharedOptions.Cache();
        var scalar = SharedOptions.Scalar("the scalar type of the code where a binding point has no //GMac.Type line (default: double)");
        var fma = SharedOptions.Fma("fuse a product into the sum it is added to (Math.FusedMultiplyAdd, Vector256.FusedMultiplyAdd, …) where a binding point has no //GMac.Fma line");
        var command = new Command("generate", "Rewrite the binding points (#region GMac blocks) of C# files.") { paths, sourcesFrom, check, stats, cache, scalar, fma };
        dsl.AddTo(command);
        UnknownOptions.RejectIn(paths, command);
        command.SetAction(r =>
        {
            var watch = Stopwatch.StartNew();
            var error = r.InvocationConfiguration.Error;
            // A list stands for the files to work on (an MSBuild project's Compile items), so with
            // one the current folder is not scanned as well unless it is named.
            var sources = SharedOptions.PathsOrCurrent(r.GetValue(paths));
            if (r.GetValue(sourcesFrom) is { } list)
            {
                if (SourceList.Read(list, error) is not { } listed) return ExitCodes.Diagnostics;
                sources = [.. r.GetValue(paths) ?? [], .. listed];
            }
            if (dsl.Resolve(r, error, out var failure) is not { } dslSources) return failure;
            var context = DslOptions.Load(dslSources, r.GetValue(cache), error);
            if (context is null) return ExitCodes.Diagnostics;
            context.DefaultScalarType = r.GetValue(scalar)!;
            context.DefaultFusedMultiplyAdd = r.GetValue(fma);
            return SourceGeneration.Run(context, sources, r.GetValue(check), r.GetValue(stats), r.InvocationConfiguration.Output, error, watch) ? ExitCodes.Success : ExitCodes.Diagnostics;
        });
        return command;
    }
}
