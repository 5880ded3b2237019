using GMac.Benchmarks.Accuracy;
using GMac.Benchmarks.Applications;
using GMac.Benchmarks.Generation;
using GMac.Benchmarks.Kernels;
using GMac.Benchmarks.Kernels.Vector;
using GMac.Dsl;
using GMac.Dsl.Generation;
using SafeFiles;

namespace GMac.Benchmarks.Reporting;

/// <summary>
/// <c>report [--quick]</c>: checks and times every kernel, counts operations, times generation, and
/// writes <c>ga-apps.md</c> and <c>ga-apps.png</c>. Both files are written whole or not at all.
/// </summary>
public static class ReportCommand
{
    public const string MarkdownFile = "ga-apps.md";
    public const string ChartFile = "ga-apps.png";

    public static int Run(IReadOnlyList<string> args, TextWriter output, TextWriter error)
    {
        var options = ReportOptions.Parse(args, out var usage);
        if (options is null)
        {
            error.WriteLine($"report: {usage}");
            error.WriteLine(ReportOptions.Usage);
            return 2;
        }
        try
        {
            Write(options, output);
            return 0;
        }
        catch (Exception e) when (e is InvalidOperationException or IOException or UnauthorizedAccessException)
        {
            error.WriteLine($"report: {e.Message}");
            return 1;
        }
    }

    private const int PairedRatioPairs = 41;
    private const int PairedRatioSliceMs = 25;

    /// <summary>
    /// Fresh processes per kernel for its generated / hand ratio (<see cref="ProcessRatioTimer"/>): an even
    /// number, half of them compiling the hand code first, each with its code placed elsewhere, since
    /// on the kernels of about a nanosecond where the JIT put the two loops moved their ratio by up to 30 %.
    /// </summary>
    private const int RatioProcesses = 8;

    private const int VectorOnlyPairs = 11;
    private const int VectorOnlySliceMs = 10;

    /// <summary>
    /// Items per batch for the vector section's main table: every kernel's columns (19 at most, 38 KB)
    /// then stay in the 48 KB L1 data cache, so the times are those of the code. At the suite's
    /// 1024 items, timed as well, kernels that do few operations per byte wait on the L2 cache.
    /// </summary>
    public const int CacheResidentBatch = 256;

    /// <summary>Checks and times the vector forms of every kernel; the section of the report, with how it was timed.</summary>
    public static string VectorSection(int pairs, int sliceMs, TextWriter log)
    {
        var timer = new VectorTimer(new PairedRatioTimer(pairs, TimeSpan.FromMilliseconds(sliceMs)), TimeSpan.FromMilliseconds(200));
        var traffic = new Dictionary<string, (int Columns, int Operations)>();
        VectorTiming[] Measure(int items)
        {
            var kernels = VectorKernelCatalog.CreateAll();
            foreach (var k in kernels)
            {
                k.Setup(items, GaApplicationBenchmarks.Seed);
                VectorKernelAgreement.Verify(k);
                traffic[k.MacroName] = (k.ColumnCount, k.Scalar.HandOperations.Total);
            }
            log.WriteLine($"report: the vector forms of {kernels.Count} kernels agree with their scalar code on {items} items; timing them in pairs");
            return kernels.Select(timer.Measure).ToArray();
        }
        var resident = Measure(CacheResidentBatch);
        var large = Measure(GaApplicationBenchmarks.BatchSize);
        return VectorTable.Section(resident, CacheResidentBatch, large, GaApplicationBenchmarks.BatchSize, traffic,
            $"Times and ratios are medians over {pairs} back-to-back pairs of {sliceMs} ms slices (the ratio taken within each pair).");
    }

    public static void Write(ReportOptions options, TextWriter log)
    {
        if (options.VectorOnly)
        {
            log.WriteLine(LoadLine());
            log.Write(VectorSection(VectorOnlyPairs, VectorOnlySliceMs, log));
            return;
        }
        var project = DslProject.Load(options.DslDirectory);
        if (project.HasErrors)
            throw new InvalidOperationException($"the DSL folder '{options.DslDirectory}' has errors: {project.Diagnostics.First(d => d.IsError)}");
        var counter = new GeneratedOperationCounter(new MacroCodeGenerator(project));

        var kernels = KernelCatalog.CreateAll();
        foreach (var k in kernels)
        {
            k.Setup(GaApplicationBenchmarks.BatchSize, GaApplicationBenchmarks.Seed);
            KernelAgreement.Verify(k);
        }
        log.WriteLine($"report: the three variants of {kernels.Count} kernels agree");

        IReadOnlyList<KernelTiming> timings;
        if (options.Quick)
        {
            var timer = new StopwatchTimer(rounds: 3, TimeSpan.FromMilliseconds(20));
            timings = kernels.Select(timer.Measure).ToArray();
        }
        else
        {
            timings = BenchmarkDotNetTimer.MeasureAll(Path.Combine(Path.GetTempPath(), "gmac-bench-artifacts"));
            log.WriteLine($"report: timing generated against hand in pairs, in {RatioProcesses} processes per kernel");
            var processes = new ProcessRatioTimer(RatioProcesses);
            timings = timings.Select(t =>
            {
                var (median, min, max) = processes.GeneratedOverHand(t.Kernel);
                return t with { PairedGeneratedOverHand = median, PairedRange = (min, max) };
            }).ToArray();
        }

        var rows = kernels.Zip(timings, (k, t) =>
        {
            try
            {
                var (operations, cycles) = counter.Measure(k);
                return new KernelRow(k, t, operations, null) { EstimatedCycles = cycles };
            }
            catch (InvalidOperationException e)
            {
                return new KernelRow(k, t, null, e.Message);
            }
        }).ToArray();

        var accuracyItems = options.Quick ? 50 : 400;
        log.WriteLine($"report: measuring accuracy on {accuracyItems} inputs per family");
        var harness = new AccuracyHarness(new MacroCodeGenerator(project), accuracyItems, GaApplicationBenchmarks.Seed);
        var accuracy = kernels.SelectMany(harness.Measure).ToArray();

        GenerationTimings? generation = null;
        if (!options.SkipGeneration)
        {
            log.WriteLine("report: timing generation of every macro");
            generation = new GenerationTimer(options.DslDirectory, warmRepeats: options.Quick ? 1 : 5).Measure();
        }

        var vectorSection = options.Quick ? VectorSection(pairs: 3, sliceMs: 5, log) : VectorSection(PairedRatioPairs, PairedRatioSliceMs, log);

        var command = "dotnet run -c Release --project bench/GMac.Benchmarks -- report" + (options.Quick ? " --quick" : "");
        var mode = options.Quick ? "quick: Stopwatch, best of 3 rounds of 20 ms" : "full: BenchmarkDotNet in process, 4 warm-ups, 10 iterations of 200 ms, median; " +
            $"generated / hand: in each of {RatioProcesses} fresh processes per kernel (every other one compiling the hand code first, and process p compiling {ProcessRatioTimer.ShiftStep}·p methods of GMac.Core before, so that each places the code elsewhere; DOTNET_JitAlignLoops=0), both run until the JIT has its final code, " +
            $"then {KernelsCommand.RatioPairs} back-to-back pairs of {KernelsCommand.SliceMs} ms slices and the median of the pairs' ratios; the median over the processes, their range in brackets";
        var markdown = MarkdownReport.Render(rows, generation, mode, command, ChartFile,
            accuracy, AccuracyTable.Section(accuracy, accuracyItems, GaApplicationBenchmarks.Seed), vectorSection);
        var png = BarChart.Render(timings);

        Directory.CreateDirectory(options.OutputDirectory);
        AtomicFile.Write(Path.Combine(options.OutputDirectory, ChartFile), png);
        AtomicFile.Write(Path.Combine(options.OutputDirectory, MarkdownFile), System.Text.Encoding.UTF8.GetBytes(markdown));
        log.WriteLine($"report: wrote {Path.Combine(options.OutputDirectory, MarkdownFile)} and {ChartFile}");
    }

    private static string LoadLine()
    {
        var load = File.Exists("/proc/loadavg") ? File.ReadAllText("/proc/loadavg").Trim() : "unknown";
        return $"report --vector-only: {DateTime.UtcNow:yyyy-MM-dd HH:mm} UTC, {Environment.ProcessorCount} logical cores, load average {load}";
    }
}
