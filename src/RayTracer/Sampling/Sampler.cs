using RayTracer.Maths;
using RayTracer.Randomness;

namespace RayTracer.Sampling;

/// <summary>
/// A store of <see cref="NumSets"/> sets of <see cref="NumSamples"/> points in the unit square, with the
/// same points mapped to the unit disk, the hemisphere and the sphere. Samples are handed out one set at
/// a time through a shuffled index table, starting at a random set, so neighbouring pixels do not
/// repeat the same pattern. The sets are fixed at construction (from <c>seed</c>); the position in them
/// is kept per thread and restarts at every pixel (see <see cref="SamplingContext"/>).
/// </summary>
public abstract class Sampler
{
    private sealed class Cursor
    {
        public long Epoch = -1;
        public long Count;
        public int Jump;
    }

    private readonly ThreadLocal<Cursor> _cursor = new(() => new Cursor());
    private readonly int[] _shuffledIndices;
    private Point2D[] _squareSamples = [];
    private Point2D[]? _diskSamples;
    private Vector3D[]? _hemisphereSamples;
    private Vector3D[]? _sphereSamples;

    public int NumSamples { get; }
    public int NumSets { get; }

    protected Sampler(int numSamples, int numSets = 83, ulong seed = 12345)
    {
        if (numSamples < 1)
            throw new ArgumentOutOfRangeException(nameof(numSamples), "A sampler needs at least one sample.");
        if (numSets < 1)
            throw new ArgumentOutOfRangeException(nameof(numSets), "A sampler needs at least one set.");
        NumSamples = numSamples;
        NumSets = numSets;
        Random = new SeededRandom(seed);
        _shuffledIndices = new int[numSamples * numSets];
    }

    /// <summary>Generator used only while the sets are built.</summary>
    protected SeededRandom Random { get; }

    /// <summary>Builds the sets; subclass constructors call this once their own fields are set.</summary>
    protected void Initialize()
    {
        var samples = new Point2D[NumSamples * NumSets];
        for (var set = 0; set < NumSets; set++)
            GenerateSet(samples.AsSpan(set * NumSamples, NumSamples));
        _squareSamples = samples;
        SetUpShuffledIndices();
    }

    /// <summary>Fills one set of points in [0,1)².</summary>
    protected abstract void GenerateSet(Span<Point2D> set);

    private void SetUpShuffledIndices()
    {
        var order = new int[NumSamples];
        for (var set = 0; set < NumSets; set++)
        {
            for (var i = 0; i < NumSamples; i++) order[i] = i;
            Random.Shuffle(order.AsSpan());
            order.CopyTo(_shuffledIndices, set * NumSamples);
        }
    }

    /// <summary>All unit-square samples, set after set (for tests and diagnostics).</summary>
    public ReadOnlySpan<Point2D> SquareSamples => _squareSamples;

    public ReadOnlySpan<Point2D> DiskSamples => _diskSamples ?? throw new InvalidOperationException("Call MapSamplesToUnitDisk first.");

    public ReadOnlySpan<Vector3D> HemisphereSamples => _hemisphereSamples ?? throw new InvalidOperationException("Call MapSamplesToHemisphere first.");

    public ReadOnlySpan<Vector3D> SphereSamples => _sphereSamples ?? throw new InvalidOperationException("Call MapSamplesToSphere first.");

    /// <summary>Shirley–Chiu concentric map: keeps the strata of the square as (distorted) strata of the disk.</summary>
    public static Point2D ConcentricDisk(Point2D unitSquare)
    {
        var sx = 2.0 * unitSquare.x - 1.0;
        var sy = 2.0 * unitSquare.y - 1.0;
        if (sx == 0.0 && sy == 0.0)
            return new Point2D(0, 0);
        double r, phi;
        if (Math.Abs(sx) > Math.Abs(sy))
        {
            r = sx;
            phi = Math.PI / 4 * (sy / sx);
        }
        else
        {
            r = sy;
            phi = Math.PI / 2 - Math.PI / 4 * (sx / sy);
        }
        return new Point2D(r * Math.Cos(phi), r * Math.Sin(phi));
    }

    /// <summary>Hemisphere around +z with density proportional to cos^e θ.</summary>
    public static Vector3D CosinePowerHemisphere(Point2D unitSquare, double e)
    {
        var cosPhi = Math.Cos(2.0 * Math.PI * unitSquare.x);
        var sinPhi = Math.Sin(2.0 * Math.PI * unitSquare.x);
        var cosTheta = Math.Pow(1.0 - unitSquare.y, 1.0 / (e + 1.0));
        var sinTheta = Math.Sqrt(Math.Max(0.0, 1.0 - cosTheta * cosTheta));
        return new Vector3D(sinTheta * cosPhi, sinTheta * sinPhi, cosTheta);
    }

    /// <summary>Uniform on the unit sphere (Archimedes: z uniform in [-1, 1]).</summary>
    public static Vector3D UniformSphere(Point2D unitSquare)
    {
        var z = 1.0 - 2.0 * unitSquare.x;
        var r = Math.Sqrt(Math.Max(0.0, 1.0 - z * z));
        var phi = 2.0 * Math.PI * unitSquare.y;
        return new Vector3D(r * Math.Cos(phi), r * Math.Sin(phi), z);
    }

    public void MapSamplesToUnitDisk() => _diskSamples ??= Array.ConvertAll(_squareSamples, ConcentricDisk);

    public void MapSamplesToHemisphere(double e)
    {
        _hemisphereSamples = Array.ConvertAll(_squareSamples, p => CosinePowerHemisphere(p, e));
    }

    public void MapSamplesToSphere() => _sphereSamples ??= Array.ConvertAll(_squareSamples, UniformSphere);

    /// <summary>Index of the next sample: walks a set in shuffled order, then jumps to a random set.</summary>
    private int NextIndex()
    {
        var cursor = _cursor.Value!;
        var epoch = SamplingContext.Epoch;
        if (cursor.Epoch != epoch)
        {
            cursor.Epoch = epoch;
            cursor.Count = 0;
        }
        if (cursor.Count % NumSamples == 0)
            cursor.Jump = SeededRandom.Current.NextInt(NumSets) * NumSamples;
        var i = (int)(cursor.Count++ % NumSamples);
        return cursor.Jump + _shuffledIndices[cursor.Jump + i];
    }

    public Point2D SampleUnitSquare() => _squareSamples[NextIndex()];

    public Point2D SampleUnitDisk() => (_diskSamples ?? throw new InvalidOperationException("Sampler was not mapped to the unit disk."))[NextIndex()];

    public Vector3D SampleHemisphere() => (_hemisphereSamples ?? throw new InvalidOperationException("Sampler was not mapped to the hemisphere."))[NextIndex()];
}
