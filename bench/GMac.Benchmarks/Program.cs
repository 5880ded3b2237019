using BenchmarkDotNet.Configs;
using BenchmarkDotNet.Jobs;
using BenchmarkDotNet.Running;
using BenchmarkDotNet.Toolchains.InProcess.Emit;
using GMac.Benchmarks.Reporting;

namespace GMac.Benchmarks;

internal static class Program
{
    private static int Main(string[] args)
    {
        if (args.Length > 0 && args[0] == "report")
            return ReportCommand.Run(args[1..], Console.Out, Console.Error);
        if (args.Length > 0 && args[0] == "kernels")
            return KernelsCommand.Run(args[1..], Console.Out, Console.Error);
        if (args.Length > 0 && args[0] == "generation")
            return Generation.GenerationCommand.Run(args[1..], Console.Out, Console.Error);

        // In process, as the report does: no host project is generated and rebuilt per benchmark.
        var config = ManualConfig.Create(DefaultConfig.Instance)
            .AddJob(Job.Default.WithToolchain(InProcessEmitToolchain.Instance))
            .WithOptions(ConfigOptions.DisableOptimizationsValidator);
        BenchmarkSwitcher.FromAssembly(typeof(Program).Assembly).Run(args, config);
        return 0;
    }
}
