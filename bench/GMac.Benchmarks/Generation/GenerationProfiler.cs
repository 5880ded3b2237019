using System.Globalization;
using GMac.Core.CodeGeneration;
using GMac.Core.Symbolic;
using GMac.Dsl;
using GMac.Dsl.Generation;
using RayTracer.Timing;

namespace GMac.Benchmarks.Generation;

/// <summary>
/// <c>generation --profile</c>: after one untimed pass over the library (JIT), generates the chosen
/// macros (all by default) cold, with a fresh generator and cache, and prints the time per stage and
/// per optimizer pass summed over them. Times are inclusive: a stage's line counts the passes and
/// simplifications it runs.
/// </summary>
public static class GenerationProfiler
{
    public static void Run(string dslDirectory, IReadOnlyCollection<string>? only, TextWriter output)
    {
        var warmUp = Fresh(dslDirectory);
        foreach (var name in warmUp.Generator.MacroNames.ToArray()) warmUp.Generator.Generate(name, warmUp.Generator.DefaultBindings(name));
        Delete(warmUp.Directory);
        ForgetWarmUp();

        var (generator, directory) = Fresh(dslDirectory);
        var names = generator.MacroNames.Where(n => only is null || only.Contains(n)).ToArray();
        var threadTime = ThreadCpuClock.IsThreadTime;
        if (threadTime) GenerationProfile.Clock = ThreadCpuClock.NowMilliseconds;
        GenerationProfile.Reset();
        GenerationProfile.Enabled = true;
        var total = GenerationProfile.Time("all macros", () =>
        {
            foreach (var name in names) generator.Generate(name, generator.DefaultBindings(name));
            return 0;
        });
        GenerationProfile.Enabled = false;
        Delete(directory);

        static string F(double x) => x.ToString("0.0", CultureInfo.InvariantCulture);
        output.WriteLine($"{names.Length} macros cold; times are {(threadTime ? "thread CPU" : "wall")} milliseconds");
        output.WriteLine("| stage or pass | ms (inclusive) | MB allocated | calls |");
        output.WriteLine("|---|---:|---:|---:|");
        foreach (var (stage, t) in GenerationProfile.Snapshot().OrderByDescending(kv => kv.Value.Ms))
            output.WriteLine($"| {stage} | {F(t.Ms)} | {F(t.Bytes / 1e6)} | {t.Calls} |");
    }

    private static (MacroCodeGenerator Generator, string Directory) Fresh(string dslDirectory)
    {
        var directory = System.IO.Directory.CreateTempSubdirectory("gmac-bench-cache-").FullName;
        var cas = new CachingCasAdapter(new RuleBasedCas(), new SimplificationCache(directory));
        return (new MacroCodeGenerator(DslProject.Load(dslDirectory), cas), directory);
    }

    private static void Delete(string directory)
    {
        try
        {
            System.IO.Directory.Delete(directory, recursive: true);
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
