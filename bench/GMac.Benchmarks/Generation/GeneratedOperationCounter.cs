using GMac.Benchmarks.Kernels;
using GMac.Core.CodeGeneration;
using GMac.Dsl.Generation;

namespace GMac.Benchmarks.Generation;

/// <summary>Operation counts of a kernel's generated variant: its binding points regenerated with the library and summed.</summary>
public sealed class GeneratedOperationCounter(MacroCodeGenerator generator)
{
    public OperationCount Count(IGaKernel kernel)
    {
        var regions = KernelRegions.RegionsOf(kernel.GetType().Name, kernel.MacroName);
        if (regions.Count == 0) throw new InvalidOperationException($"{kernel.GetType().Name} has no binding point of macro {kernel.MacroName}.");
        int adds = 0, muls = 0, divs = 0, calls = 0;
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
        }
        return new OperationCount(adds, muls, divs, calls);
    }
}
