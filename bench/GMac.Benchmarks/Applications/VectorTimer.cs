using System.Runtime.Intrinsics;
using GMac.Benchmarks.Kernels;
using GMac.Benchmarks.Kernels.Vector;

namespace GMac.Benchmarks.Applications;

/// <summary>
/// Times a kernel's vector forms against its generated scalar code (and the generated Vector256
/// against hand-written Vector256 code), in pairs, each form first run until the JIT has its final
/// code (<see cref="JitWarmUp"/>, in slices of <paramref name="warmUp"/>).
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

    private void WarmUp(Action run) => JitWarmUp.Run(run, warmUp);
}
