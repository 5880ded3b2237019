using GMac.Benchmarks.Applications;
using GMac.Benchmarks.Kernels;

namespace GMac.Benchmarks.Reporting;

/// <summary>One line of the report: a kernel's timings and operation counts (generated ones null when generation failed).</summary>
public sealed record KernelRow(IGaKernel Kernel, KernelTiming Timing, OperationCount? GeneratedOperations, string? GenerationError)
{
    /// <summary>The cost model's estimate for the generated code, cycles per item.</summary>
    public double? EstimatedCycles { get; init; }
}
