using RayTracer.Maths;

namespace RayTracer.Sampling;

/// <summary>Independent uniform points: no stratification (the baseline the others improve on).</summary>
public sealed class PureRandomSampler : Sampler
{
    public PureRandomSampler(int numSamples, int numSets = 83, ulong seed = 12345)
        : base(numSamples, numSets, seed)
    {
        Initialize();
    }

    protected override void GenerateSet(Span<Point2D> set)
    {
        for (var i = 0; i < set.Length; i++)
            set[i] = new Point2D(Random.NextDouble(), Random.NextDouble());
    }
}
