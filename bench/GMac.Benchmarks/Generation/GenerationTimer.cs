using System.Diagnostics;
using GMac.Core.Symbolic;
using GMac.Dsl;
using GMac.Dsl.Generation;

namespace GMac.Benchmarks.Generation;

/// <summary>
/// Times code generation itself. Cold means a fresh <see cref="DslProject"/>, a fresh generator and a
/// fresh simplification cache over an empty folder; warm means the same generator asked again. One
/// untimed pass over the library comes first so that JIT compilation is not charged to the first macro.
/// </summary>
public sealed class GenerationTimer(string dslDirectory, int warmRepeats, IReadOnlyCollection<string>? only = null)
{
    public GenerationTimings Measure()
    {
        var firstPass = Stopwatch.StartNew();
        WarmUpPass();
        firstPass.Stop();
        // Tiered compilation recompiles hot methods on a background thread, and only after they have
        // been called again once it starts counting: until that settles, a "cold" macro would partly
        // run unoptimized code and its time would depend on how far the JIT had got. More untimed
        // passes run until one compiles no new method (or a limit is reached).
        var settle = Stopwatch.StartNew();
        for (var pass = 0; pass < MaxSettlingPasses; pass++)
        {
            var before = System.Runtime.JitInfo.GetCompiledMethodCount();
            WarmUpPass();
            Thread.Sleep(200); // let the background compilations queued by this pass finish
            if (System.Runtime.JitInfo.GetCompiledMethodCount() == before) break;
        }
        settle.Stop();
        ForgetWarmUp();

        var load = Stopwatch.StartNew();
        var project = DslProject.Load(dslDirectory);
        load.Stop();
        if (project.HasErrors)
            throw new InvalidOperationException($"the DSL folder '{dslDirectory}' has errors: {project.Diagnostics.First(d => d.IsError)}");

        var macros = new List<MacroGenerationTiming>();
        foreach (var name in new MacroCodeGenerator(project).MacroNames.Where(n => only is null || only.Contains(n)).ToArray())
        {
            var (generator, directory) = Fresh();
            var bindings = generator.DefaultBindings(name);
            var cold = Stopwatch.StartNew();
            var outcome = generator.Generate(name, bindings);
            cold.Stop();
            var warm = new double[warmRepeats];
            for (var r = 0; r < warmRepeats; r++)
            {
                var w = Stopwatch.StartNew();
                generator.Generate(name, bindings);
                warm[r] = w.Elapsed.TotalMilliseconds;
            }
            Array.Sort(warm);
            var error = outcome.Succeeded ? null : string.Join("; ", outcome.Errors.Select(e => $"{e.Code}: {e.Message}"));
            macros.Add(new MacroGenerationTiming(name, cold.Elapsed.TotalMilliseconds, warm[warm.Length / 2], error));
            Delete(directory);
        }

        // The library is timed several times, each run cold (a fresh generator and cache, and a
        // full collection first so nothing a previous run interned or remembered survives); one
        // run moves by tens of milliseconds with the collector's timing, so the median is quoted.
        var colds = new double[LibraryRuns];
        var warms = new double[LibraryRuns];
        var parallelColds = new double[LibraryRuns];
        var cores = new ParallelOptions { MaxDegreeOfParallelism = Environment.ProcessorCount };
        for (var run = 0; run < LibraryRuns; run++)
        {
            ForgetWarmUp();
            var (library, libraryDir) = Fresh();
            var names = library.MacroNames.Where(n => only is null || only.Contains(n)).ToArray();
            var libraryCold = Stopwatch.StartNew();
            foreach (var name in names) library.Generate(name, library.DefaultBindings(name));
            colds[run] = libraryCold.Elapsed.TotalMilliseconds;
            var libraryWarm = Stopwatch.StartNew();
            foreach (var name in names) library.Generate(name, library.DefaultBindings(name));
            warms[run] = libraryWarm.Elapsed.TotalMilliseconds;
            Delete(libraryDir);

            // the same with the macros shared out over every core by one generator, as `gmac generate` shares out files
            ForgetWarmUp();
            (library, libraryDir) = Fresh();
            var parallelCold = Stopwatch.StartNew();
            Parallel.ForEach(names, cores, name => library.Generate(name, library.DefaultBindings(name)));
            parallelColds[run] = parallelCold.Elapsed.TotalMilliseconds;
            Delete(libraryDir);
        }

        return new GenerationTimings(macros, firstPass.Elapsed.TotalMilliseconds, load.Elapsed.TotalMilliseconds, colds, Median(warms), parallelColds)
        {
            SettlingMs = settle.Elapsed.TotalMilliseconds,
        };
    }

    /// <summary>Untimed passes after the first, at most, while the JIT is still compiling.</summary>
    public const int MaxSettlingPasses = 6;

    private void WarmUpPass()
    {
        var (generator, directory) = Fresh();
        foreach (var name in generator.MacroNames.ToArray()) generator.Generate(name, generator.DefaultBindings(name));
        Delete(directory);
    }

    /// <summary>How many times the whole library is generated cold, one core and every core.</summary>
    public const int LibraryRuns = 5;

    internal static double Median(IReadOnlyList<double> values)
    {
        var sorted = values.Order().ToArray();
        return sorted.Length % 2 == 1 ? sorted[sorted.Length / 2] : (sorted[sorted.Length / 2 - 1] + sorted[sorted.Length / 2]) / 2;
    }

    private (MacroCodeGenerator Generator, string CacheDirectory) Fresh()
    {
        var directory = Directory.CreateTempSubdirectory("gmac-bench-cache-").FullName;
        var cas = new CachingCasAdapter(new RuleBasedCas(), new SimplificationCache(directory));
        return (new MacroCodeGenerator(DslProject.Load(dslDirectory), cas), directory);
    }

    private static void Delete(string directory)
    {
        try
        {
            Directory.Delete(directory, recursive: true);
        }
        catch (IOException)
        {
            // a leftover temp folder is harmless
        }
    }

    /// <summary>
    /// Collects what the untimed pass left: values are interned weakly and some results are
    /// remembered per value, so leftovers of that pass would otherwise answer the cold run.
    /// </summary>
    private static void ForgetWarmUp()
    {
        GC.Collect();
        GC.WaitForPendingFinalizers();
        GC.Collect();
    }
}
