using BenchmarkDotNet.Attributes;
using GMac.Benchmarks.Kernels;
using GMac.Benchmarks.Kernels.Values;
using GMac.Core.Algebra;
using Twister;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks;

/// <summary>
/// A three-twist cascade (rotation about x by 2πu; rotation about a skew axis through a point by 3u;
/// a full twist about a third axis by 5u with a slide of 0.7u) applied to one seed point at
/// <see cref="BatchSize"/> values of u: Twister's generated kernels, the same versors on
/// <c>Multivector&lt;double&gt;</c>, and three hand-written Rodrigues rotations. The hand version writes
/// the rotation about x directly; Twister does the same through its coordinate-axis fast path (a kernel
/// generated with the literal axis), so both sides use the best formula each has for it.
/// </summary>
public class TwistCascadeBenchmarks
{
    public const int BatchSize = 1024;

    private static readonly Vec3 Seed = new(0.8, -0.3, 0.5);
    private static readonly Vec3 SkewAxis = new(1, 2, -0.5), SkewOrigin = new(0.2, -0.4, 1);
    private static readonly Vec3 FullAxis = new(-0.3, 0.4, 1.2), FullOrigin = new(1, 0.5, -0.5);

    private readonly double[] _u = new double[BatchSize];
    private readonly Vec3[] _out = new Vec3[BatchSize];
    private TwistCascade _cascade = null!;
    private Vec3 _skewUnit, _fullUnit;

    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(20261121);
        for (var i = 0; i < BatchSize; i++) _u[i] = random.NextDouble();
        _cascade = TwistCascade.Empty
            .RotateAboutX(2 * Math.PI, ParameterMap.U)
            .RotateAbout(new(SkewAxis.x, SkewAxis.y, SkewAxis.z), new(SkewOrigin.x, SkewOrigin.y, SkewOrigin.z), 3, ParameterMap.U)
            .Then(new FullTwist(new(FullAxis.x, FullAxis.y, FullAxis.z), new(FullOrigin.x, FullOrigin.y, FullOrigin.z), 5, ParameterMap.U, 0.7, ParameterMap.U));
        _skewUnit = Unit(SkewAxis);
        _fullUnit = Unit(FullAxis);
        Verify();
    }

    [Benchmark]
    public void Generated()
    {
        var seed = new TwistablePoint(Seed.x, Seed.y, Seed.z);
        for (var i = 0; i < _u.Length; i++)
        {
            var p = _cascade.Apply(seed, _u[i], 0);
            _out[i] = new(p.x, p.y, p.z);
        }
    }

    [Benchmark]
    public void Direct()
    {
        for (var i = 0; i < _u.Length; i++) _out[i] = DirectAt(_u[i]);
    }

    [Benchmark(Baseline = true)]
    public void Hand()
    {
        for (var i = 0; i < _u.Length; i++) _out[i] = HandAt(_u[i]);
    }

    /// <summary>Refuses to time variants that disagree.</summary>
    private void Verify()
    {
        foreach (var u in _u.Take(16))
        {
            var p = _cascade.Apply(new TwistablePoint(Seed.x, Seed.y, Seed.z), u, 0);
            var (d, h) = (DirectAt(u), HandAt(u));
            foreach (var (a, b) in new[] { (p.x, h.x), (p.y, h.y), (p.z, h.z), (d.x, h.x), (d.y, h.y), (d.z, h.z) })
                if (Math.Abs(a - b) > 1e-9) throw new InvalidOperationException($"the cascade variants disagree at u = {u}: {a} vs {b}");
        }
    }

    private static Vec3 DirectAt(double u)
    {
        var versor = Translation(0.7 * u * ConformalVector(FullAxis))
            .Gp(GeneralRotation(ConformalVector(FullOrigin), ConformalVector(FullAxis), 5 * u))
            .Gp(GeneralRotation(ConformalVector(SkewOrigin), ConformalVector(SkewAxis), 3 * u))
            .Gp(GeneralRotation(ConformalVector(default), ConformalVector(new(1, 0, 0)), 2 * Math.PI * u));
        return ToVec3(versor.Apply(Point(Seed)));
    }

    private static Multivector<double> Translation(Multivector<double> t) => CgaOne - 0.5 * t.Op(CgaNi);

    private static Multivector<double> GeneralRotation(Multivector<double> p, Multivector<double> axis, double angle)
    {
        var plane = axis.Lcp(CgaI3);
        var rotation = Math.Cos(angle / 2) * CgaOne - Math.Sin(angle / 2) * (plane / plane.Norm());
        var vp = Translation(p);
        return vp.Gp(rotation).Gp(vp.Inverse());
    }

    private Vec3 HandAt(double u)
    {
        // Rotation about x through the origin.
        double c = Math.Cos(2 * Math.PI * u), s = Math.Sin(2 * Math.PI * u);
        var p = new Vec3(Seed.x, Seed.y * c - Seed.z * s, Seed.y * s + Seed.z * c);
        p = Rodrigues(p, _skewUnit, SkewOrigin, 3 * u);
        p = Rodrigues(p, _fullUnit, FullOrigin, 5 * u);
        var slide = 0.7 * u;
        return new(p.x + slide * FullAxis.x, p.y + slide * FullAxis.y, p.z + slide * FullAxis.z);
    }

    /// <summary>Rodrigues' rotation of x − o about the unit axis k by φ, moved back by o.</summary>
    private static Vec3 Rodrigues(Vec3 x, Vec3 k, Vec3 o, double angle)
    {
        double c = Math.Cos(angle), s = Math.Sin(angle);
        double ux = x.x - o.x, uy = x.y - o.y, uz = x.z - o.z;
        var f = (k.x * ux + k.y * uy + k.z * uz) * (1 - c);
        return new(o.x + ux * c + (k.y * uz - k.z * uy) * s + k.x * f,
            o.y + uy * c + (k.z * ux - k.x * uz) * s + k.y * f,
            o.z + uz * c + (k.x * uy - k.y * ux) * s + k.z * f);
    }

    private static Vec3 Unit(Vec3 a)
    {
        var length = Math.Sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
        return new(a.x / length, a.y / length, a.z / length);
    }
}
