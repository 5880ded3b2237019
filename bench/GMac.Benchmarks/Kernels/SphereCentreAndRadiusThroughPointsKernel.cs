using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using GMac.Core.Algebra;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>
/// The radius of the sphere through four points, computed relative to the first point. Only the
/// radius is bound: next to a centre near 1e5 a normwise error would not see the radius's digits,
/// and the radius is what reading a dual sphere back loses far from the origin.
/// </summary>
public sealed class SphereCentreAndRadiusThroughPointsKernel : GaKernel<Vec3Quad, double>
{
    private static readonly Multivector<double> E3Ii = -E3I;

    public override string MacroName => "SphereCentreAndRadiusThroughPoints";
    public override string Source => "circumsphere from differences to p1";

    /// <summary>
    /// Counted by hand: nine differences (9 add), three squared lengths (9 mul, 6 add), three cross
    /// products (18 mul, 9 add), the volume (3 mul, 2 add), ½ / volume (1 div), three centre offsets
    /// (12 mul, 6 add), the squared radius (3 mul, 2 add) and its square root (1 call).
    /// </summary>
    public override OperationCount HandOperations => new(Additions: 34, Multiplications: 45, Divisions: 1, Calls: 1);

    protected override Vec3Quad CreateInput(Random random) => new()
    {
        P1 = new(Signed(random), Signed(random), Signed(random)),
        P2 = new(Signed(random), Signed(random), Signed(random)),
        P3 = new(Signed(random), Signed(random), Signed(random)),
        P4 = new(Signed(random), Signed(random), Signed(random)),
    };

    protected override double[] Components(double radius) => [radius];

    protected override void RunGenerated(Vec3Quad[] inputs, double[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Generated(in inputs[i], out outputs[i]);
    }

    protected override void RunDirect(Vec3Quad[] inputs, double[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Direct(in inputs[i]);
    }

    protected override void RunHand(Vec3Quad[] inputs, double[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Hand(in inputs[i]);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Generated(in Vec3Quad q, out double radius)
    {
        #region GMac : SphereCentreAndRadiusThroughPoints
        //GMac.Bind("p1", "Point3D", "q.P1");
        //GMac.Bind("p2", "Point3D", "q.P2");
        //GMac.Bind("p3", "Point3D", "q.P3");
        //GMac.Bind("p4", "Point3D", "q.P4");
        //GMac.Bind("radius.1", "<radius>");
        double tmp0 = q.P2.x - q.P1.x;
        double tmp1 = q.P2.y - q.P1.y;
        double tmp2 = q.P2.z - q.P1.z;
        double tmp3 = q.P3.x - q.P1.x;
        double tmp4 = q.P3.y - q.P1.y;
        double tmp5 = q.P3.z - q.P1.z;
        double tmp6 = q.P4.x - q.P1.x;
        double tmp7 = q.P4.y - q.P1.y;
        double tmp8 = q.P4.z - q.P1.z;
        double tmp9 = tmp0 * tmp4 - tmp1 * tmp3;
        double tmp10 = tmp0 * tmp5 - tmp2 * tmp3;
        double tmp11 = tmp1 * tmp5 - tmp2 * tmp4;
        double tmp12 = tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2;
        double tmp13 = tmp3 * tmp3 + tmp4 * tmp4 + tmp5 * tmp5;
        double tmp14 = tmp6 * tmp6 + tmp7 * tmp7 + tmp8 * tmp8;
        double tmp15 = 0.5 / (tmp11 * tmp6 + tmp8 * tmp9 - tmp10 * tmp7);
        double tmp16 = (tmp12 * (tmp4 * tmp8 - tmp5 * tmp7) + tmp13 * (tmp2 * tmp7 - tmp1 * tmp8) + tmp11 * tmp14) * tmp15;
        double tmp17 = (tmp12 * (tmp5 * tmp6 - tmp3 * tmp8) + tmp13 * (tmp0 * tmp8 - tmp2 * tmp6) - tmp10 * tmp14) * tmp15;
        double tmp18 = (tmp12 * (tmp3 * tmp7 - tmp4 * tmp6) + tmp13 * (tmp1 * tmp6 - tmp0 * tmp7) + tmp14 * tmp9) * tmp15;
        radius = Math.Sqrt(tmp16 * tmp16 + tmp17 * tmp17 + tmp18 * tmp18);
        #endregion
    }

    /// <summary>The macro's steps with the numeric multivectors of e3d.</summary>
    public static double Direct(in Vec3Quad q)
    {
        var p1 = Of(q.P1);
        var (d2, d3, d4) = (Of(q.P2) - p1, Of(q.P3) - p1, Of(q.P4) - p1);
        var volume = d2.Op(d3).Op(d4).Lcp(E3Ii).ScalarPart;
        var sum = d2.Sp(d2).ScalarPart * d3.Op(d4).Lcp(E3Ii) + d3.Sp(d3).ScalarPart * d4.Op(d2).Lcp(E3Ii) + d4.Sp(d4).ScalarPart * d2.Op(d3).Lcp(E3Ii);
        var c = sum / (2 * volume);
        return Math.Sqrt(c.Sp(c).ScalarPart);
    }

    /// <summary>
    /// The circumcentre's offset from p1 by Cramer's rule on 2 c·dᵢ = |dᵢ|²:
    /// c = (|a|² (b × d) + |b|² (d × a) + |d|² (a × b)) / (2 a·(b × d)).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double Hand(in Vec3Quad q)
    {
        ref readonly var p1 = ref q.P1;
        double ax = q.P2.x - p1.x, ay = q.P2.y - p1.y, az = q.P2.z - p1.z;
        double bx = q.P3.x - p1.x, by = q.P3.y - p1.y, bz = q.P3.z - p1.z;
        double dx = q.P4.x - p1.x, dy = q.P4.y - p1.y, dz = q.P4.z - p1.z;
        double a2 = ax * ax + ay * ay + az * az, b2 = bx * bx + by * by + bz * bz, d2 = dx * dx + dy * dy + dz * dz;
        double bdx = by * dz - bz * dy, bdy = bz * dx - bx * dz, bdz = bx * dy - by * dx;
        double dax = dy * az - dz * ay, day = dz * ax - dx * az, daz = dx * ay - dy * ax;
        double abx = ay * bz - az * by, aby = az * bx - ax * bz, abz = ax * by - ay * bx;
        var half = 0.5 / (ax * bdx + ay * bdy + az * bdz);
        var cx = (a2 * bdx + b2 * dax + d2 * abx) * half;
        var cy = (a2 * bdy + b2 * day + d2 * aby) * half;
        var cz = (a2 * bdz + b2 * daz + d2 * abz) * half;
        return Math.Sqrt(cx * cx + cy * cy + cz * cz);
    }
}
