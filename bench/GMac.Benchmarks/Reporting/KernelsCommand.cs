using GMac.Benchmarks.Accuracy;
using GMac.Benchmarks.Applications;
using GMac.Benchmarks.Generation;
using GMac.Benchmarks.Kernels;
using GMac.Dsl;
using GMac.Dsl.Generation;

namespace GMac.Benchmarks.Reporting;

/// <summary>
/// <c>kernels NAME…</c>: the report's scalar figures for a few kernels only (operations of the
/// generated and hand code, the paired generated / hand time ratio, the accuracy families), in
/// seconds rather than the full report's minutes, for checking a change of the generator.
/// </summary>
public static class KernelsCommand
{
    private const int Pairs = 41;
    private const int SliceMs = 25;
    private const int AccuracyItems = 400;

    public static int Run(IReadOnlyList<string> args, TextWriter output, TextWriter error)
    {
        if (args.Count == 0 || args.Any(a => !KernelCatalog.Names.Contains(a)))
        {
            error.WriteLine($"usage: GMac.Benchmarks kernels NAME... (known: {string.Join(", ", KernelCatalog.Names)})");
            return 2;
        }
        var dsl = Path.Combine(RepositoryRoot(), "dsl");
        var project = DslProject.Load(dsl);
        var counter = new GeneratedOperationCounter(new MacroCodeGenerator(project));
        var harness = new AccuracyHarness(new MacroCodeGenerator(project), AccuracyItems, GaApplicationBenchmarks.Seed);
        var paired = new PairedRatioTimer(Pairs, TimeSpan.FromMilliseconds(SliceMs));
        output.WriteLine($"load average {(File.Exists("/proc/loadavg") ? File.ReadAllText("/proc/loadavg").Trim() : "unknown")}; " +
                         $"paired ratio: median of {Pairs} pairs of {SliceMs} ms slices");
        foreach (var name in args)
        {
            var kernel = KernelCatalog.Create(name);
            kernel.Setup(GaApplicationBenchmarks.BatchSize, GaApplicationBenchmarks.Seed);
            KernelAgreement.Verify(kernel);
            var (ratio, generatedNs, handNs) = paired.Pair(kernel.Count, () => kernel.Time(Variant.Generated), () => kernel.Time(Variant.Hand));
            output.WriteLine($"{name}: ops generated {counter.Count(kernel)}, hand {kernel.HandOperations}");
            output.WriteLine($"  time generated {generatedNs:0.00} ns, hand {handNs:0.00} ns, paired ratio {ratio:0.000}");
            foreach (var row in harness.Measure(kernel))
                output.WriteLine($"  accuracy {row.Family.Name}: generated max {row.GeneratedMax:0.0e0} (median {row.GeneratedMedian:0.0e0}), hand max {row.HandMax:0.0e0}, ratio {row.Ratio:0.00}");
        }
        return 0;
    }

    private static string RepositoryRoot()
    {
        for (var dir = new DirectoryInfo(Directory.GetCurrentDirectory()); dir is not null; dir = dir.Parent)
            if (File.Exists(Path.Combine(dir.FullName, "GMac.sln"))) return dir.FullName;
        throw new InvalidOperationException("cannot find the repository (GMac.sln) above the current folder");
    }
}
