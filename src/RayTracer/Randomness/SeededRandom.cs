using System.Numerics;
using System.Runtime.CompilerServices;

namespace RayTracer.Randomness;

/// <summary>
/// Deterministic xoshiro256** generator. A stream is fixed by (seed, stream index), so renderers
/// reseed per pixel or per tile and the image never depends on how work is spread over threads.
/// </summary>
public sealed class SeededRandom
{
    [ThreadStatic]
    private static SeededRandom? _current;

    private ulong _s0, _s1, _s2, _s3;

    public SeededRandom(ulong seed, ulong stream = 0)
    {
        Reseed(seed, stream);
    }

    /// <summary>
    /// The calling thread's generator (created seeded with 0). Code that renders a tile calls
    /// <see cref="Reseed"/> on it with (image seed, tile index) before using it.
    /// </summary>
    public static SeededRandom Current => _current ??= new SeededRandom(0);

    public void Reseed(ulong seed, ulong stream = 0)
    {
        // SplitMix64 expands the pair into the 256-bit state; mixing the stream in first
        // keeps neighbouring stream indices uncorrelated.
        ulong x = seed ^ (stream * 0xD1B54A32D192ED03UL + 0x8BB84B93962EACC9UL);
        _s0 = SplitMix(ref x);
        _s1 = SplitMix(ref x);
        _s2 = SplitMix(ref x);
        _s3 = SplitMix(ref x);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public ulong NextULong()
    {
        ulong result = BitOperations.RotateLeft(_s1 * 5, 7) * 9;
        ulong t = _s1 << 17;
        _s2 ^= _s0;
        _s3 ^= _s1;
        _s1 ^= _s2;
        _s0 ^= _s3;
        _s2 ^= t;
        _s3 = BitOperations.RotateLeft(_s3, 45);
        return result;
    }

    /// <summary>Uniform in [0, 1) with 53 random bits.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public double NextDouble() => (NextULong() >> 11) * (1.0 / (1UL << 53));

    public double NextDouble(double min, double max) => min + (max - min) * NextDouble();

    /// <summary>Uniform integer in [0, maxExclusive), without modulo bias.</summary>
    public int NextInt(int maxExclusive)
    {
        ArgumentOutOfRangeException.ThrowIfNegativeOrZero(maxExclusive);
        ulong bound = (ulong)maxExclusive;
        ulong threshold = (0UL - bound) % bound;
        while (true)
        {
            ulong r = NextULong();
            if (r >= threshold)
            {
                return (int)(r % bound);
            }
        }
    }

    /// <summary>Uniform integer in [minInclusive, maxExclusive).</summary>
    public int NextInt(int minInclusive, int maxExclusive) =>
        minInclusive + NextInt(maxExclusive - minInclusive);

    /// <summary>Fisher–Yates shuffle (samplers shuffle their index tables with it).</summary>
    public void Shuffle<T>(Span<T> items)
    {
        for (int i = items.Length - 1; i > 0; i--)
        {
            int j = NextInt(i + 1);
            (items[i], items[j]) = (items[j], items[i]);
        }
    }

    private static ulong SplitMix(ref ulong x)
    {
        ulong z = x += 0x9E3779B97F4A7C15UL;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
        return z ^ (z >> 31);
    }
}
