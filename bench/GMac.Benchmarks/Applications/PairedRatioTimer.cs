using System.Diagnostics;
using GMac.Benchmarks.Kernels;

namespace GMac.Benchmarks.Applications;

/// <summary>
/// The generated / hand ratio of one kernel, timed in pairs: short slices of the two variants back
/// to back (in alternating order), the ratio taken within each pair and the median over the pairs.
/// On a shared machine whose speed drifts over seconds, separate runs of the two variants can land
/// in different phases and move a ratio by 20 % or more; two slices a few milliseconds apart see the
/// same machine.
/// </summary>
public sealed class PairedRatioTimer(int pairs, TimeSpan sliceTime)
{
    public double GeneratedOverHand(IGaKernel kernel)
    {
        kernel.Time(Variant.Generated); // JIT and caches
        kernel.Time(Variant.Hand);
        var ratios = new double[pairs];
        for (var p = 0; p < pairs; p++)
        {
            double generated, hand;
            if (p % 2 == 0)
            {
                generated = Slice(kernel, Variant.Generated);
                hand = Slice(kernel, Variant.Hand);
            }
            else
            {
                hand = Slice(kernel, Variant.Hand);
                generated = Slice(kernel, Variant.Generated);
            }
            ratios[p] = generated / hand;
        }
        Array.Sort(ratios);
        return pairs % 2 == 1 ? ratios[pairs / 2] : (ratios[pairs / 2 - 1] + ratios[pairs / 2]) / 2;
    }

    /// <summary>Nanoseconds per item over one slice: whole batches until the slice time is up.</summary>
    private double Slice(IGaKernel kernel, Variant variant)
    {
        var batches = 0;
        var watch = Stopwatch.StartNew();
        do
        {
            kernel.Time(variant);
            batches++;
        } while (watch.Elapsed < sliceTime);
        return watch.Elapsed.TotalNanoseconds / ((double)batches * kernel.Count);
    }
}
