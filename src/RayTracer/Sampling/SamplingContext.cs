using RayTracer.Randomness;

namespace RayTracer.Sampling;

/// <summary>
/// Per-thread rendering context. The renderer calls <see cref="BeginPixel"/> before each pixel: it reseeds
/// the thread's generator from (image seed, pixel index) and starts a new epoch, which makes every sampler
/// restart its cursor. A pixel's value therefore depends only on the seed, never on which thread drew it.
/// </summary>
public static class SamplingContext
{
    [ThreadStatic]
    private static long _epoch;

    /// <summary>Changes whenever the current thread begins a new pixel.</summary>
    public static long Epoch => _epoch;

    public static void BeginPixel(ulong seed, ulong pixelIndex)
    {
        SeededRandom.Current.Reseed(seed, pixelIndex);
        _epoch++;
    }
}
