using System.Runtime.CompilerServices;
using BenchmarkDotNet.Attributes;
using BenchmarkDotNet.Configs;
using GMac.Benchmarks.Kernels;
using GMac.Benchmarks.Kernels.Values;

namespace GMac.Benchmarks.Applications;

/// <summary>
/// The two kernels whose generated code trails the hand code in time with no more operations:
/// Gram–Schmidt by rejections and the closest points of skew lines. Each is timed three ways on the
/// same 1024 random inputs: generated, the textbook hand form of the report, and the generated
/// form written by hand ("accurate hand"). Where the accurate hand form costs what the generated
/// code does, the gap is the price of the form (a longer chain of dependent operations, which
/// the textbook form avoids by losing digits on ill-conditioned inputs), not of the generator.
/// Run: <c>dotnet run -c Release --project bench/GMac.Benchmarks -- --filter '*AccurateForm*'</c>.
/// </summary>
[GroupBenchmarksBy(BenchmarkLogicalGroupRule.ByCategory)]
[CategoriesColumn]
public class AccurateFormBenchmarks
{
    private const int Items = 1024;

    private readonly Vec3Triple[] _triples = new Vec3Triple[Items];
    private readonly Vec3Triple[] _orthogonal = new Vec3Triple[Items];
    private readonly LinePair[] _lines = new LinePair[Items];
    private readonly LineParameters[] _parameters = new LineParameters[Items];

    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(20261124);
        Vec3 Next() => new(random.NextDouble() * 2 - 1, random.NextDouble() * 2 - 1, random.NextDouble() * 2 - 1);
        for (var i = 0; i < Items; i++)
        {
            _triples[i] = new Vec3Triple { A = Next(), B = Next(), C = Next() };
            _lines[i] = new LinePair { P1 = Next(), D1 = Next(), P2 = Next(), D2 = Next() };
        }
    }

    [Benchmark(Baseline = true), BenchmarkCategory("GramSchmidtRejection")]
    public void RejectionHand()
    {
        for (var i = 0; i < Items; i++) GramSchmidtRejectionKernel.Hand(in _triples[i], out _orthogonal[i]);
    }

    [Benchmark, BenchmarkCategory("GramSchmidtRejection")]
    public void RejectionGenerated()
    {
        for (var i = 0; i < Items; i++) GramSchmidtRejectionKernel.Generated(in _triples[i], out _orthogonal[i]);
    }

    [Benchmark, BenchmarkCategory("GramSchmidtRejection")]
    public void RejectionAccurateHand()
    {
        for (var i = 0; i < Items; i++) AccurateRejection(in _triples[i], out _orthogonal[i]);
    }

    [Benchmark(Baseline = true), BenchmarkCategory("SkewLinesClosestPoints")]
    public void SkewLinesHand()
    {
        for (var i = 0; i < Items; i++) SkewLinesClosestPointsKernel.Hand(in _lines[i], out _parameters[i]);
    }

    [Benchmark, BenchmarkCategory("SkewLinesClosestPoints")]
    public void SkewLinesGenerated()
    {
        for (var i = 0; i < Items; i++) SkewLinesClosestPointsKernel.Generated(in _lines[i], out _parameters[i]);
    }

    [Benchmark, BenchmarkCategory("SkewLinesClosestPoints")]
    public void SkewLinesAccurateHand()
    {
        for (var i = 0; i < Items; i++) AccurateSkewLines(in _lines[i], out _parameters[i]);
    }

    /// <summary>As the textbook form, but the normal is v1 × w2 (after the first division) rather than v1 × v2.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void AccurateRejection(in Vec3Triple v, out Vec3Triple w)
    {
        ref readonly var a = ref v.A;
        ref readonly var b = ref v.B;
        ref readonly var c = ref v.C;
        var k = (a.x * b.x + a.y * b.y + a.z * b.z) / (a.x * a.x + a.y * a.y + a.z * a.z);
        w.A = a;
        double bx = b.x - k * a.x, by = b.y - k * a.y, bz = b.z - k * a.z;
        (w.B.x, w.B.y, w.B.z) = (bx, by, bz);
        var nx = a.y * bz - a.z * by;
        var ny = a.z * bx - a.x * bz;
        var nz = a.x * by - a.y * bx;
        var s = (c.x * nx + c.y * ny + c.z * nz) / (nx * nx + ny * ny + nz * nz);
        (w.C.x, w.C.y, w.C.z) = (s * nx, s * ny, s * nz);
    }

    /// <summary>t1 = D2 · (n × d) / |n|², t2 = D1 · (n × d) / |n|² with n = D1 × D2, d = P2 − P1: no Gram determinant a c − b².</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void AccurateSkewLines(in LinePair l, out LineParameters t)
    {
        ref readonly var u = ref l.D1;
        ref readonly var v = ref l.D2;
        double dx = l.P2.x - l.P1.x, dy = l.P2.y - l.P1.y, dz = l.P2.z - l.P1.z;
        double nx = u.y * v.z - u.z * v.y, ny = u.z * v.x - u.x * v.z, nz = u.x * v.y - u.y * v.x;
        double mx = ny * dz - nz * dy, my = nz * dx - nx * dz, mz = nx * dy - ny * dx;
        var inverse = 1 / (nx * nx + ny * ny + nz * nz);
        t.T1 = (v.x * mx + v.y * my + v.z * mz) * inverse;
        t.T2 = (u.x * mx + u.y * my + u.z * mz) * inverse;
    }
}
