using System.Diagnostics;
using GMac.Benchmarks.Kernels;

namespace GMac.Benchmarks.Applications;

/// <summary>
/// The quick timing path: a Stopwatch loop, best of a few rounds, each round long enough to be far
/// above timer resolution. For smoke runs; the full report uses BenchmarkDotNet.
/// </summary>
public sealed class StopwatchTimer(int rounds, TimeSpan roundTime)
{
    public KernelTiming Measure(IGaKernel kernel)
    {
        double Time(Variant v)
        {
            kernel.Time(v); // JIT and caches
            var best = double.MaxValue;
            for (var r = 0; r < rounds; r++)
            {
                var batches = 0;
                var watch = Stopwatch.StartNew();
                do
                {
                    kernel.Time(v);
                    batches++;
                } while (watch.Elapsed < roundTime);
                best = Math.Min(best, watch.Elapsed.TotalNanoseconds / ((double)batches * kernel.Count));
            }
            return best;
        }
        return new KernelTiming(kernel.MacroName, Time(Variant.Generated), Time(Variant.Direct), Time(Variant.Hand));
    }
}
