using RayTracer.Maths;

namespace RayTracer.Sampling;

/// <summary>
/// Hammersley point set (i/n, radical inverse of i in base 2): deterministic and well spread. Every set is
/// the same, so only one is stored.
/// </summary>
public sealed class HammersleySampler : Sampler
{
    public HammersleySampler(int numSamples, ulong seed = 12345)
        : base(numSamples, 1, seed)
    {
        Initialize();
    }

    public static double RadicalInverse(int i)
    {
        double x = 0, f = 0.5;
        for (var j = (uint)i; j != 0; j >>= 1)
        {
            x += f * (j & 1);
            f *= 0.5;
        }
        return x;
    }

    protected override void GenerateSet(Span<Point2D> set)
    {
        for (var i = 0; i < set.Length; i++)
            set[i] = new Point2D((double)i / set.Length, RadicalInverse(i));
    }
}
