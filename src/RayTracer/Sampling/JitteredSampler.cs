using RayTracer.Maths;

namespace RayTracer.Sampling;

/// <summary>One random point in each cell of an n×n grid; the sample count is rounded down to a square.</summary>
public sealed class JitteredSampler : Sampler
{
    public JitteredSampler(int numSamples, int numSets = 83, ulong seed = 12345)
        : base(RegularSampler.SquareCount(numSamples), numSets, seed)
    {
        Initialize();
    }

    protected override void GenerateSet(Span<Point2D> set)
    {
        var n = (int)Math.Round(Math.Sqrt(NumSamples));
        for (var p = 0; p < n; p++)
        for (var q = 0; q < n; q++)
            set[p * n + q] = new Point2D((q + Random.NextDouble()) / n, (p + Random.NextDouble()) / n);
    }
}
