namespace Twister.Tessellation;

/// <summary>
/// SplitMix64: a small generator whose sequence is fixed by its seed on every platform and runtime,
/// so a tessellation is reproducible.
/// </summary>
internal sealed class ProbeRandom
{
    private ulong _state;

    public ProbeRandom(int seed) => _state = (ulong)(uint)seed * 0x9E3779B97F4A7C15UL + 0x632BE59BD9B4E019UL;

    /// <summary>
    /// A generator owned by one edge or face, named by a few integers: its probes are the same whichever
    /// face asks and whatever was probed before.
    /// </summary>
    public static ProbeRandom Keyed(int seed, long a, long b, long c, long d)
    {
        var random = new ProbeRandom(seed);
        foreach (var k in (ReadOnlySpan<long>)[a, b, c, d])
        {
            random._state = Mix(random._state ^ (ulong)k);
        }

        return random;
    }

    /// <summary>Uniform in [0, 1).</summary>
    public double NextDouble()
    {
        _state += 0x9E3779B97F4A7C15UL;
        return (Mix(_state) >> 11) * (1.0 / (1UL << 53));
    }

    private static ulong Mix(ulong z)
    {
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
        return z ^ (z >> 31);
    }
}
