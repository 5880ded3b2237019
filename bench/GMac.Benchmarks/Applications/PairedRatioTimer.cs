using System.Diagnostics;
using GMac.Benchmarks.Kernels;

namespace GMac.Benchmarks.Applications;

/// <summary>
/// The generated / hand ratio of one kernel, timed in pairs: short slices of the two variants back
/// to back (in alternating order), the ratio taken within each pair and the median over the pairs.
/// On a shared machine whose speed drifts over seconds, separate runs of the two variants can land
/// in different phases and move a ratio by 20 % or more; two slices a few milliseconds apart see the
/// same machine. With <paramref name="warmUp"/>, both variants first run until the JIT has its final
/// code for them (<see cref="JitWarmUp"/>); without, once each (for callers that warm up themselves,
/// or quick runs).
/// </summary>
public sealed class PairedRatioTimer(int pairs, TimeSpan sliceTime, TimeSpan? warmUp = null)
{
    public double GeneratedOverHand(IGaKernel kernel) =>
        Pair(kernel.Count, () => kernel.Time(Variant.Generated), () => kernel.Time(Variant.Hand)).Ratio;

    /// <summary>
    /// The median over the pairs of first / second (nanoseconds per item of a slice of each), and the
    /// median nanoseconds per item of each; each action runs one whole batch of <paramref name="items"/>.
    /// </summary>
    public (double Ratio, double FirstNs, double SecondNs) Pair(int items, Action first, Action second)
    {
        if (warmUp is { } slice)
        {
            JitWarmUp.Run(first, slice);
            JitWarmUp.Run(second, slice);
        }
        first(); // caches
        second();
        var ratios = new double[pairs];
        var (a, b) = (new double[pairs], new double[pairs]);
        for (var p = 0; p < pairs; p++)
        {
            if (p % 2 == 0)
            {
                a[p] = Slice(items, first);
                b[p] = Slice(items, second);
            }
            else
            {
                b[p] = Slice(items, second);
                a[p] = Slice(items, first);
            }
            ratios[p] = a[p] / b[p];
        }
        return (Median(ratios), Median(a), Median(b));
    }

    private double Median(double[] values)
    {
        Array.Sort(values);
        return pairs % 2 == 1 ? values[pairs / 2] : (values[pairs / 2 - 1] + values[pairs / 2]) / 2;
    }

    /// <summary>
    /// Nanoseconds per item over one slice: whole batches until the slice time is up. The clock is read
    /// after groups of batches that double until a group takes at least <see cref="MinimumGroupTime"/>:
    /// reading it costs tens of nanoseconds here, a sixth of a 1024-item batch of the fastest vector
    /// kernels, and would otherwise be timed as part of the kernel.
    /// </summary>
    private double Slice(int items, Action run)
    {
        long batches = 0;
        var group = 1;
        var watch = Stopwatch.StartNew();
        var groupStart = TimeSpan.Zero;
        do
        {
            for (var b = 0; b < group; b++) run();
            batches += group;
            var now = watch.Elapsed;
            if (now - groupStart < MinimumGroupTime) group *= 2;
            groupStart = now;
        } while (groupStart < sliceTime);
        return groupStart.TotalNanoseconds / ((double)batches * items);
    }

    private static readonly TimeSpan MinimumGroupTime = TimeSpan.FromMicroseconds(20);
}
