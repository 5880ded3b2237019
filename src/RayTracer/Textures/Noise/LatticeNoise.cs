using RayTracer.Maths;
namespace RayTracer.Textures.Noise;

/// <summary>
/// Value noise on the integer lattice: pseudo-random values in [-1, 1] stored at lattice points and
/// hashed through a permutation table (period 256 in each axis), interpolated by a subclass.
/// Fractal sums are built on top: fBm, turbulence and wrapped fBm.
/// </summary>
public abstract class LatticeNoise
{
    public const int TableSize = 256;
    private const int Mask = TableSize - 1;

    private readonly byte[] _permutation = new byte[TableSize];
    private readonly double[] _values = new double[TableSize];

    public int Octaves { get; }
    public double Lacunarity { get; }
    public double Gain { get; }

    // Bounds of the fractal sum, used to map fBm into [0, 1].
    private readonly double _fbmMax;

    protected LatticeNoise(int octaves = 1, double lacunarity = 2.0, double gain = 0.5, int seed = 253)
    {
        if (octaves < 1)
            throw new ArgumentOutOfRangeException(nameof(octaves), "A noise needs at least one octave.");
        Octaves = octaves;
        Lacunarity = lacunarity;
        Gain = gain;

        var random = new Random(seed);
        for (var i = 0; i < TableSize; i++)
        {
            _values[i] = 2.0 * random.NextDouble() - 1.0;
            _permutation[i] = (byte)i;
        }
        // Fisher–Yates so the permutation is a true bijection.
        for (var i = TableSize - 1; i > 0; i--)
        {
            var j = random.Next(i + 1);
            (_permutation[i], _permutation[j]) = (_permutation[j], _permutation[i]);
        }

        _fbmMax = Math.Abs(gain - 1.0) < Tolerances.RelativeRounding ? octaves : (1.0 - Math.Pow(gain, octaves)) / (1.0 - gain);
    }

    private int Perm(int i) => _permutation[i & Mask];

    /// <summary>The random value attached to lattice point (i, j, k), in [-1, 1].</summary>
    public double LatticeValue(int i, int j, int k) => _values[Perm(i + Perm(j + Perm(k)))];

    /// <summary>Single-octave noise at a point, in [-1, 1].</summary>
    public abstract double ValueNoise(double x, double y, double z);

    /// <summary>Sum of octaves, amplitude <see cref="Gain"/>^j at frequency <see cref="Lacunarity"/>^j; in [-max, max].</summary>
    public double FractalSum(double x, double y, double z)
    {
        double amplitude = 1, frequency = 1, sum = 0;
        for (var j = 0; j < Octaves; j++)
        {
            sum += amplitude * ValueNoise(frequency * x, frequency * y, frequency * z);
            amplitude *= Gain;
            frequency *= Lacunarity;
        }
        return sum;
    }

    /// <summary>Fractional Brownian motion mapped to [0, 1].</summary>
    public double Fbm(double x, double y, double z) => (FractalSum(x, y, z) + _fbmMax) / (2.0 * _fbmMax);

    /// <summary>Sum of absolute octave values, mapped to [0, 1]; creases where the noise crosses zero.</summary>
    public double Turbulence(double x, double y, double z)
    {
        double amplitude = 1, frequency = 1, sum = 0;
        for (var j = 0; j < Octaves; j++)
        {
            sum += amplitude * Math.Abs(ValueNoise(frequency * x, frequency * y, frequency * z));
            amplitude *= Gain;
            frequency *= Lacunarity;
        }
        return sum / _fbmMax;
    }

    /// <summary>Fractional part of a scaled fBm: bands that wrap around, in [0, 1).</summary>
    public double WrappedFbm(double x, double y, double z, double expansion)
    {
        var value = expansion * Fbm(x, y, z);
        return value - Math.Floor(value);
    }

    protected static int Floor(double v)
    {
        var i = (int)v;
        return v < i ? i - 1 : i;
    }
}
