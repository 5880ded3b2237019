using RayTracer.Maths;

namespace RayTracer.Sampling;

/// <summary>
/// Latin hypercube: one sample in every row and every column of an n×n grid, obtained by jittering
/// along the diagonal and then shuffling the x and y coordinates independently.
/// </summary>
public sealed class NRooksSampler : Sampler
{
    public NRooksSampler(int numSamples, int numSets = 83, ulong seed = 12345)
        : base(numSamples, numSets, seed)
    {
        Initialize();
    }

    protected override void GenerateSet(Span<Point2D> set)
    {
        var n = set.Length;
        Span<double> xs = stackalloc double[n];
        Span<double> ys = stackalloc double[n];
        for (var i = 0; i < n; i++)
        {
            xs[i] = (i + Random.NextDouble()) / n;
            ys[i] = (i + Random.NextDouble()) / n;
        }
        Random.Shuffle(xs);
        Random.Shuffle(ys);
        for (var i = 0; i < n; i++)
            set[i] = new Point2D(xs[i], ys[i]);
    }
}
