using GMac.Benchmarks.Kernels;
using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Cost;
using GMac.Dsl.Generation;

namespace GMac.Benchmarks.Generation;

/// <summary>
/// Operation counts and the cost model's time estimate of a kernel's generated variant: its binding
/// points regenerated with the library and summed.
/// </summary>
public sealed class GeneratedOperationCounter(MacroCodeGenerator generator)
{
    public OperationCount Count(IGaKernel kernel) => Measure(kernel).Operations;

    /// <summary>The operations and the estimated cycles per item (<see cref="TimeModel"/>, Zen figures, no fused multiply-add).</summary>
    public (OperationCount Operations, double EstimatedCycles) Measure(IGaKernel kernel)
    {
        var regions = KernelRegions.RegionsOf(kernel.GetType().Name, kernel.MacroName);
        if (regions.Count == 0) throw new InvalidOperationException($"{kernel.GetType().Name} has no binding point of macro {kernel.MacroName}.");
        int adds = 0, muls = 0, divs = 0, calls = 0;
        var cycles = 0.0;
        foreach (var bindings in regions)
        {
            var outcome = generator.Generate(kernel.MacroName, bindings);
            if (!outcome.Succeeded)
                throw new InvalidOperationException($"{kernel.MacroName}: {string.Join("; ", outcome.Errors.Select(e => $"{e.Code}: {e.Message}"))}");
            var s = outcome.Result!.Statistics;
            adds += s.Additions;
            muls += s.Multiplications;
            divs += s.Divisions;
            calls += s.Calls;
            cycles += TimeModel.Estimate(outcome.Result.Block).Cycles;
        }
        return (new OperationCount(adds, muls, divs, calls), cycles);
    }
}
