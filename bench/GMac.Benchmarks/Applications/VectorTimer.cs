using System.Runtime.Intrinsics;
using GMac.Benchmarks.Kernels;
using GMac.Benchmarks.Kernels.Vector;

namespace GMac.Benchmarks.Applications;

/// <summary>
/// Times a kernel's vector forms against its generated scalar code (and the generated Vector256
/// against hand-written Vector256 code), in pairs. Each form first runs in slices of <paramref name="warmUp"/>
/// until one made the JIT compile nothing:
/// the vector functions of .NET (Sin, SinCos, Exp…) were measured up to 10 times slower in a process's
/// first runs than after the JIT's final code replaced the first (late, on a loaded machine); timed
/// before that, a kernel calling them looks slower than its scalar code.
/// </summary>
public sealed class VectorTimer(PairedRatioTimer timer, TimeSpan warmUp)
{
    public VectorTiming Measure(VectorKernel kernel)
    {
        var n = kernel.Count;
        void Scalar() => kernel.Scalar.Time(Variant.Generated);
        WarmUp(Scalar);
        foreach (var v in Enum.GetValues<VectorVariant>().Where(kernel.Supports)) WarmUp(() => kernel.Time(v));
        var v256 = timer.Pair(n, Scalar, () => kernel.Time(VectorVariant.Generated256));
        (double Ratio, double FirstNs, double SecondNs)? v512 = Vector512.IsHardwareAccelerated
            ? timer.Pair(n, Scalar, () => kernel.Time(VectorVariant.Generated512))
            : null;
        (double Ratio, double FirstNs, double SecondNs)? hand = kernel.HasHand
            ? timer.Pair(n, () => kernel.Time(VectorVariant.Generated256), () => kernel.Time(VectorVariant.Hand256))
            : null;
        return new VectorTiming(kernel.MacroName, v256.FirstNs, v256.SecondNs, v256.Ratio,
            v512?.SecondNs, v512?.Ratio, hand?.SecondNs, hand?.Ratio);
    }

    /// <summary>Runs in slices of the warm-up time until a whole slice made the JIT compile nothing (at most 5 s).</summary>
    private void WarmUp(Action run)
    {
        var total = System.Diagnostics.Stopwatch.StartNew();
        long before;
        do
        {
            before = System.Runtime.JitInfo.GetCompiledMethodCount();
            var slice = System.Diagnostics.Stopwatch.StartNew();
            do run(); while (slice.Elapsed < warmUp);
        } while (System.Runtime.JitInfo.GetCompiledMethodCount() != before && total.Elapsed < TimeSpan.FromSeconds(5));
    }
}
