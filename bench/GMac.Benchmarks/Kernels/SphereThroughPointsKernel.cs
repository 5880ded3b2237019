using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>(3.73), (3.76) the dual sphere ω = (p1 ^ p2 ^ p3 ^ p4) ⌋ I⁻¹ through four points.</summary>
public sealed class SphereThroughPointsKernel : GaKernel<Vec3Quad, DualSphere>
{
    public override string MacroName => "SphereThroughPoints";
    public override string Source => "thesis (3.73), (3.76)";

    /// <summary>
    /// Counted by hand: four ½|p|² (16 mul, 8 add), twelve differences to p1 (12 add), six 2×2 minors
    /// (12 mul, 6 add), four 3×3 determinants (12 mul, 8 add), the e1^e2^e3^ni coefficient (4 mul, 3 add).
    /// </summary>
    public override OperationCount HandOperations => new(Additions: 37, Multiplications: 44, Divisions: 0, Calls: 0);

    protected override Vec3Quad CreateInput(Random random) => new()
    {
        P1 = new(Signed(random), Signed(random), Signed(random)),
        P2 = new(Signed(random), Signed(random), Signed(random)),
        P3 = new(Signed(random), Signed(random), Signed(random)),
        P4 = new(Signed(random), Signed(random), Signed(random)),
    };

    protected override double[] Components(DualSphere s) => [s.No, s.E1, s.E2, s.E3, s.Ni];

    protected override void RunGenerated(Vec3Quad[] inputs, DualSphere[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Generated(in inputs[i], out outputs[i]);
    }

    protected override void RunDirect(Vec3Quad[] inputs, DualSphere[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Direct(in inputs[i]);
    }

    protected override void RunHand(Vec3Quad[] inputs, DualSphere[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Hand(in inputs[i], out outputs[i]);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Generated(in Vec3Quad q, out DualSphere s)
    {
        #region GMac : SphereThroughPoints
        //GMac.Bind("p1", "ConformalPoint3D", "q.P1");
        //GMac.Bind("p2", "ConformalPoint3D", "q.P2");
        //GMac.Bind("p3", "ConformalPoint3D", "q.P3");
        //GMac.Bind("p4", "ConformalPoint3D", "q.P4");
        //GMac.Bind("omega.no", "<s.No>");
        //GMac.Bind("omega.e1", "<s.E1>");
        //GMac.Bind("omega.e2", "<s.E2>");
        //GMac.Bind("omega.e3", "<s.E3>");
        //GMac.Bind("omega.ni", "<s.Ni>");
        double tmp25 = q.P1.x;
        double tmp0 = q.P2.x - tmp25;
        double tmp26 = q.P1.y;
        double tmp1 = q.P2.y - tmp26;
        double tmp27 = q.P1.z;
        double tmp2 = q.P2.z - tmp27;
        double tmp3 = 0.5 * (tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2);
        double tmp4 = q.P3.x - tmp25;
        double tmp5 = q.P3.y - tmp26;
        double tmp6 = q.P3.z - tmp27;
        double tmp7 = 0.5 * (tmp4 * tmp4 + tmp5 * tmp5 + tmp6 * tmp6);
        double tmp8 = q.P4.x - tmp25;
        double tmp9 = q.P4.y - tmp26;
        double tmp10 = tmp9 * tmp4 - tmp8 * tmp5;
        double tmp11 = q.P4.z - tmp27;
        double tmp12 = 0.5 * (tmp8 * tmp8 + tmp9 * tmp9 + tmp11 * tmp11);
        double tmp13 = tmp12 * tmp4 - tmp8 * tmp7;
        double tmp14 = tmp12 * tmp5 - tmp9 * tmp7;
        double tmp15 = tmp13 * tmp1 - (tmp14 * tmp0 + tmp3 * tmp10);
        double tmp16 = tmp12 * tmp6 - tmp11 * tmp7;
        double tmp17 = tmp11 * tmp4 - tmp8 * tmp6;
        double tmp18 = tmp16 * tmp0 + tmp3 * tmp17 - tmp13 * tmp2;
        double tmp19 = tmp11 * tmp5 - tmp9 * tmp6;
        double tmp20 = tmp1 * tmp17 - (tmp19 * tmp0 + tmp2 * tmp10);
        double tmp21 = tmp18 + tmp20 * tmp26;
        s.E2 = tmp21;
        double tmp22 = tmp20 * tmp27 + tmp15;
        s.E3 = tmp22;
        s.No = tmp20;
        double tmp23 = tmp19 * tmp3 + tmp16 * tmp1 - tmp14 * tmp2;
        double tmp24 = tmp20 * tmp25 - tmp23;
        s.E1 = tmp24;
        s.Ni = 0.5 * (tmp25 * (tmp24 - tmp23) + tmp26 * (tmp18 + tmp21) + tmp27 * (tmp22 + tmp15));
        #endregion
    }

    public static DualSphere Direct(in Vec3Quad q)
    {
        var sigma = Point(q.P1).Op(Point(q.P2)).Op(Point(q.P3)).Op(Point(q.P4));
        var omega = sigma.Lcp(CgaIi);
        return new DualSphere { No = omega["no"], E1 = omega["e1"], E2 = omega["e2"], E3 = omega["e3"], Ni = omega["ni"] };
    }

    /// <summary>
    /// The coefficients of p1^p2^p3^p4 are the 4×4 minors of the rows (1, x, y, z, ½|p|²); subtracting
    /// the first row turns the four with the no column into 3×3 determinants of differences, and the
    /// fifth is their cofactor expansion along p1. The dual permutes them with signs.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Hand(in Vec3Quad q, out DualSphere s)
    {
        ref readonly var p1 = ref q.P1;
        ref readonly var p2 = ref q.P2;
        ref readonly var p3 = ref q.P3;
        ref readonly var p4 = ref q.P4;
        var n1 = 0.5 * (p1.x * p1.x + p1.y * p1.y + p1.z * p1.z);
        double ax = p2.x - p1.x, ay = p2.y - p1.y, az = p2.z - p1.z, an = 0.5 * (p2.x * p2.x + p2.y * p2.y + p2.z * p2.z) - n1;
        double bx = p3.x - p1.x, by = p3.y - p1.y, bz = p3.z - p1.z, bn = 0.5 * (p3.x * p3.x + p3.y * p3.y + p3.z * p3.z) - n1;
        double cx = p4.x - p1.x, cy = p4.y - p1.y, cz = p4.z - p1.z, cn = 0.5 * (p4.x * p4.x + p4.y * p4.y + p4.z * p4.z) - n1;
        double mxy = bx * cy - by * cx, mxz = bx * cz - bz * cx, myz = by * cz - bz * cy;
        double mxn = bx * cn - bn * cx, myn = by * cn - bn * cy, mzn = bz * cn - bn * cz;
        var xyz = ax * myz - ay * mxz + az * mxy;
        var xyn = ax * myn - ay * mxn + an * mxy;
        var xzn = ax * mzn - az * mxn + an * mxz;
        var yzn = ay * mzn - az * myn + an * myz;
        s.No = -xyz;
        s.E1 = -yzn;
        s.E2 = xzn;
        s.E3 = -xyn;
        s.Ni = n1 * xyz - p1.x * yzn + p1.y * xzn - p1.z * xyn;
    }
}
