using RayTracer.Maths;

namespace RayTracer.Sampling;

/// <summary>
/// Chiu–Shirley–Wang multi-jittering: jittered on the n×n grid and n-rooks on the n²×n² subgrid at once.
/// Starts from the canonical arrangement and shuffles x within columns and y within rows, which keeps both
/// properties. The sample count is rounded down to a square.
/// </summary>
public sealed class MultiJitteredSampler : Sampler
{
    public MultiJitteredSampler(int numSamples, int numSets = 83, ulong seed = 12345)
        : base(RegularSampler.SquareCount(numSamples), numSets, seed)
    {
        Initialize();
    }

    protected override void GenerateSet(Span<Point2D> set)
    {
        var n = (int)Math.Round(Math.Sqrt(NumSamples));
        var subcell = 1.0 / NumSamples;
        for (var i = 0; i < n; i++)
        for (var j = 0; j < n; j++)
            set[i * n + j] = new Point2D(
                (i * n + j) * subcell + Random.NextDouble() * subcell,
                (j * n + i) * subcell + Random.NextDouble() * subcell);

        // Swapping the x offsets of two cells in the same column (or y offsets in the same row)
        // moves the samples between subcolumns without leaving their cells.
        for (var i = 0; i < n; i++)
        for (var j = 0; j < n; j++)
        {
            var k = Random.NextInt(j, n);
            var a = set[i * n + j];
            var b = set[i * n + k];
            set[i * n + j] = new Point2D(b.x, a.y);
            set[i * n + k] = new Point2D(a.x, b.y);
        }
        for (var i = 0; i < n; i++)
        for (var j = 0; j < n; j++)
        {
            var k = Random.NextInt(j, n);
            var a = set[j * n + i];
            var b = set[k * n + i];
            set[j * n + i] = new Point2D(a.x, b.y);
            set[k * n + i] = new Point2D(b.x, a.y);
        }
    }
}
