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
/// <c>--hand-first</c> runs (and compiles) the hand code first; <c>--code-shift N</c> compiles N other methods before
/// (<see cref="CodePlacement"/>); <c>--ratio</c> prints only the paired ratios, one machine-readable
/// line per kernel (<see cref="RatioLine"/>): the report runs it in fresh processes.
/// </summary>
public static class KernelsCommand
{
    private const int Pairs = 41;

    /// <summary>Fewer pairs per process in ratio mode: the report runs it in several processes per kernel.</summary>
    public const int RatioPairs = 21;
    public const int SliceMs = 25;
    private const int AccuracyItems = 400;

    /// <summary>Slices of each variant run until the JIT has its final code, before the pairs.</summary>
    public static readonly TimeSpan WarmUpSlice = TimeSpan.FromMilliseconds(100);

    public const string RatioLine = "ratio";

    public static int Run(IReadOnlyList<string> args, TextWriter output, TextWriter error)
    {
        var ratioOnly = args.Contains("--ratio");
        var handFirst = args.Contains("--hand-first");
        var shift = args.ToList().IndexOf("--code-shift");
        var shiftMethods = 0;
        if (shift >= 0 && (shift + 1 >= args.Count || !int.TryParse(args[shift + 1], out shiftMethods) || shiftMethods < 0))
        {
            error.WriteLine("kernels: --code-shift takes a count of methods, 0 or more");
            return 2;
        }
        args = args.Where((a, i) => a is not ("--ratio" or "--hand-first") && (shift < 0 || i != shift && i != shift + 1)).ToArray();
        if (args.Count == 0 || args.Any(a => !KernelCatalog.Names.Contains(a)))
        {
            error.WriteLine($"usage: GMac.Benchmarks kernels [--ratio] [--hand-first] [--code-shift N] NAME... (known: {string.Join(", ", KernelCatalog.Names)})");
            return 2;
        }
        CodePlacement.Shift(shiftMethods);
        if (ratioOnly) return RatiosOnly(args, handFirst, output);
        var dsl = Path.Combine(RepositoryRoot(), "dsl");
        var project = DslProject.Load(dsl);
        var counter = new GeneratedOperationCounter(new MacroCodeGenerator(project));
        var harness = new AccuracyHarness(new MacroCodeGenerator(project), AccuracyItems, GaApplicationBenchmarks.Seed);
        var paired = new PairedRatioTimer(Pairs, TimeSpan.FromMilliseconds(SliceMs), WarmUpSlice);
        output.WriteLine($"load average {(File.Exists("/proc/loadavg") ? File.ReadAllText("/proc/loadavg").Trim() : "unknown")}; " +
                         $"paired ratio: median of {Pairs} pairs of {SliceMs} ms slices");
        foreach (var name in args)
        {
            var (kernel, ratio, generatedNs, handNs) = TimeInPairs(name, paired, handFirst);
            output.WriteLine($"{name}: ops generated {counter.Count(kernel)}, hand {kernel.HandOperations}");
            output.WriteLine($"  time generated {generatedNs:0.00} ns, hand {handNs:0.00} ns, paired ratio {ratio:0.000}");
            foreach (var row in harness.Measure(kernel))
                output.WriteLine($"  accuracy {row.Family.Name}: generated max {row.GeneratedMax:0.0e0} (median {row.GeneratedMedian:0.0e0}), hand max {row.HandMax:0.0e0}, ratio {row.Ratio:0.00}");
        }
        return 0;
    }

    /// <summary>
    /// One line per kernel: <c>ratio NAME generated/hand generated-ns hand-ns</c>. With
    /// <paramref name="handFirst"/> the hand code is run (and so compiled) first: where the JIT places
    /// code and when it replaces it differ from process to process and by what came first.
    /// </summary>
    private static int RatiosOnly(IReadOnlyList<string> names, bool handFirst, TextWriter output)
    {
        var paired = new PairedRatioTimer(RatioPairs, TimeSpan.FromMilliseconds(SliceMs), WarmUpSlice);
        foreach (var name in names)
        {
            var (_, ratio, generatedNs, handNs) = TimeInPairs(name, paired, handFirst);
            output.WriteLine(FormattableString.Invariant($"{RatioLine} {name} {ratio:R} {generatedNs:R} {handNs:R}"));
        }
        return 0;
    }

    /// <summary>
    /// The kernel set up and checked against its other variants, then its generated / hand ratio and
    /// the two times per item, timed in pairs (the hand code run, and so compiled, first if asked).
    /// </summary>
    private static (IGaKernel Kernel, double Ratio, double GeneratedNs, double HandNs) TimeInPairs(string name, PairedRatioTimer paired, bool handFirst)
    {
        var kernel = KernelCatalog.Create(name);
        kernel.Setup(GaApplicationBenchmarks.BatchSize, GaApplicationBenchmarks.Seed);
        KernelAgreement.Verify(kernel);
        void Generated() => kernel.Time(Variant.Generated);
        void Hand() => kernel.Time(Variant.Hand);
        var (ratio, generatedNs, handNs) = handFirst ? Invert(paired.Pair(kernel.Count, Hand, Generated)) : paired.Pair(kernel.Count, Generated, Hand);
        return (kernel, ratio, generatedNs, handNs);
    }

    /// <summary>Hand / generated figures as generated / hand: the median of the inverses is the inverse of the median (odd count).</summary>
    private static (double, double, double) Invert((double Ratio, double FirstNs, double SecondNs) r) => (1 / r.Ratio, r.SecondNs, r.FirstNs);

    private static string RepositoryRoot()
    {
        for (var dir = new DirectoryInfo(Directory.GetCurrentDirectory()); dir is not null; dir = dir.Parent)
            if (File.Exists(Path.Combine(dir.FullName, "GMac.sln"))) return dir.FullName;
        throw new InvalidOperationException("cannot find the repository (GMac.sln) above the current folder");
    }
}
