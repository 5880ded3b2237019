using RayTracer.Maths;

namespace RayTracer.Sampling;

/// <summary>Cell centres of an n×n grid; the sample count is rounded down to a square.</summary>
public sealed class RegularSampler : Sampler
{
    public RegularSampler(int numSamples, int numSets = 1, ulong seed = 12345)
        : base(SquareCount(numSamples), numSets, seed)
    {
        Initialize();
    }

    internal static int SquareCount(int numSamples)
    {
        var n = (int)Math.Sqrt(numSamples);
        return Math.Max(1, n * n);
    }

    protected override void GenerateSet(Span<Point2D> set)
    {
        var n = (int)Math.Round(Math.Sqrt(NumSamples));
        for (var p = 0; p < n; p++)
        for (var q = 0; q < n; q++)
            set[p * n + q] = new Point2D((q + 0.5) / n, (p + 0.5) / n);
    }
}
