using System.Globalization;

namespace GMac.Benchmarks.Generation;

/// <summary>
/// <c>generation [--dsl DIR] [--macro NAME]...</c>: the generation suite of the report alone, printed as a
/// table (every macro cold and warm, then the whole library), so it can be measured without timing kernels;
/// <c>--profile</c> prints the time per stage and optimizer pass instead.
/// </summary>
public static class GenerationCommand
{
    public const string Usage = "usage: GMac.Benchmarks generation [--dsl DIR] [--macro NAME]... [--profile]";

    public static int Run(IReadOnlyList<string> args, TextWriter output, TextWriter error)
    {
        string? dsl = null;
        var macros = new List<string>();
        var profile = false;
        for (var i = 0; i < args.Count; i++)
        {
            if (args[i] == "--profile")
            {
                profile = true;
                continue;
            }
            if (args[i] is "--dsl" or "--macro" && i + 1 < args.Count)
            {
                if (args[i] == "--dsl") dsl = args[++i];
                else macros.Add(args[++i]);
                continue;
            }
            error.WriteLine($"generation: unknown or incomplete argument '{args[i]}'");
            error.WriteLine(Usage);
            return 2;
        }
        dsl ??= Path.Combine(Directory.GetCurrentDirectory(), "dsl");
        if (!Directory.Exists(dsl))
        {
            error.WriteLine($"generation: no DSL folder '{dsl}'; pass --dsl");
            return 2;
        }
        try
        {
            if (profile)
            {
                GenerationProfiler.Run(dsl, macros.Count == 0 ? null : macros, output);
                return 0;
            }
            var timings = new GenerationTimer(dsl, warmRepeats: 5, macros.Count == 0 ? null : macros).Measure();
            Write(timings, output);
            return timings.Macros.Any(m => m.Error is not null) ? 1 : 0;
        }
        catch (InvalidOperationException e)
        {
            error.WriteLine($"generation: {e.Message}");
            return 1;
        }
    }

    private static void Write(GenerationTimings timings, TextWriter output)
    {
        static string F(double ms) => ms.ToString(ms < 10 ? "0.00" : ms < 100 ? "0.0" : "0", CultureInfo.InvariantCulture);
        output.WriteLine($"first pass (JIT included): {F(timings.FirstPassMs)} ms; until the JIT settled: {F(timings.SettlingMs)} ms more; loading dsl: {F(timings.LoadMs)} ms");
        output.WriteLine($"whole library: cold {F(timings.LibraryColdMs)} ms (median of {timings.LibraryColdRuns.Count} cold runs: {string.Join(", ", timings.LibraryColdRuns.Select(F))}), warm {F(timings.LibraryWarmMs)} ms ({timings.Macros.Count} macros)");
        output.WriteLine($"whole library on {Environment.ProcessorCount} cores: cold {F(timings.LibraryParallelColdMs)} ms (median of {timings.LibraryParallelColdRuns.Count} cold runs: {string.Join(", ", timings.LibraryParallelColdRuns.Select(F))})");
        output.WriteLine("| macro | cold ms | warm ms |");
        output.WriteLine("|---|---:|---:|");
        foreach (var m in timings.Macros.OrderByDescending(m => m.ColdMs))
            output.WriteLine($"| {m.Macro} | {F(m.ColdMs)} | {F(m.WarmMs)} |{(m.Error is null ? "" : $" error: {m.Error}")}");
    }
}
