using BenchmarkDotNet.Configs;
using BenchmarkDotNet.Jobs;
using BenchmarkDotNet.Loggers;
using BenchmarkDotNet.Running;
using BenchmarkDotNet.Toolchains.InProcess.Emit;

namespace GMac.Benchmarks.Applications;

/// <summary>
/// The full timing path: BenchmarkDotNet, in process. A separate host process per benchmark would
/// rebuild this project (and regenerate its binding points) 45 times for one report.
/// </summary>
public static class BenchmarkDotNetTimer
{
    public static IReadOnlyList<KernelTiming> MeasureAll(string artifactsDirectory)
    {
        var job = Job.Default
            .WithToolchain(InProcessEmitToolchain.Instance)
            .WithWarmupCount(4)
            .WithIterationCount(10)
            .WithIterationTime(Perfolizer.Horology.TimeInterval.FromMilliseconds(200));
        var config = ManualConfig.CreateEmpty()
            .AddColumnProvider(DefaultConfig.Instance.GetColumnProviders().ToArray())
            .AddLogger(ConsoleLogger.Default)
            .AddJob(job)
            .WithArtifactsPath(artifactsDirectory)
            .WithOptions(ConfigOptions.DisableOptimizationsValidator | ConfigOptions.JoinSummary);
        var summary = BenchmarkRunner.Run<GaApplicationBenchmarks>(config);

        var median = new Dictionary<(string Kernel, string Method), double>();
        foreach (var report in summary.Reports)
        {
            var kernel = (string)report.BenchmarkCase.Parameters[nameof(GaApplicationBenchmarks.Kernel)];
            var method = report.BenchmarkCase.Descriptor.WorkloadMethod.Name;
            if (report.ResultStatistics is not { } stats)
                throw new InvalidOperationException($"BenchmarkDotNet produced no result for {kernel} {method} (did its agreement check fail? see the log above).");
            // The median resists the load spikes of a shared machine better than the mean.
            median[(kernel, method)] = stats.Median / GaApplicationBenchmarks.BatchSize;
        }
        return GaApplicationBenchmarks.KernelNames
            .Select(k => new KernelTiming(k, median[(k, "Generated")], median[(k, "Direct")], median[(k, "Hand")]))
            .ToArray();
    }
}
