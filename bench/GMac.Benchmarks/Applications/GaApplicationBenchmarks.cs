using BenchmarkDotNet.Attributes;
using GMac.Benchmarks.Kernels;

namespace GMac.Benchmarks.Applications;

/// <summary>
/// Thesis §7.1 (Figure 7-2): each application kernel in its generated, direct and hand-written form,
/// over one batch of <see cref="BatchSize"/> fixed random inputs per invocation.
/// </summary>
public class GaApplicationBenchmarks
{
    public const int BatchSize = 1024;
    public const int Seed = 20261121;

    private IGaKernel _kernel = null!;

    [ParamsSource(nameof(KernelNames))]
    public string Kernel { get; set; } = "";

    public static IEnumerable<string> KernelNames => KernelCatalog.Names;

    /// <summary>A variant that computes something else must not be timed at all.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _kernel = KernelCatalog.Create(Kernel);
        _kernel.Setup(BatchSize, Seed);
        KernelAgreement.Verify(_kernel);
    }

    [Benchmark]
    public void Generated() => _kernel.Time(Variant.Generated);

    [Benchmark]
    public void Direct() => _kernel.Time(Variant.Direct);

    [Benchmark(Baseline = true)]
    public void Hand() => _kernel.Time(Variant.Hand);
}
