using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>(3.82) the circle through three points, p ∧ q ∧ r of normalized conformal points.</summary>
public sealed class CircleThroughPointsKernel : GaKernel<Vec3Triple, ConformalCircle>
{
    public override string MacroName => "CircleThroughPoints";
    public override string Source => "thesis (3.82)";

    /// <summary>
    /// Counted by hand: a = q − p, b = r − p (6 add); α = ½ a·(p + q), β = ½ b·(p + r) (10 add, 8 mul);
    /// ½|p|² (2 add, 4 mul); a ∧ b (3 add, 6 mul); c = β a − α b (3 add, 6 mul); p·(a × b) (2 add, 3 mul);
    /// p ∧ c + ½|p|² a ∧ b (6 add, 9 mul).
    /// </summary>
    public override OperationCount HandOperations => new(Additions: 32, Multiplications: 36, Divisions: 0, Calls: 0);

    protected override Vec3Triple CreateInput(Random random) => new()
    {
        A = new(Signed(random), Signed(random), Signed(random)),
        B = new(Signed(random), Signed(random), Signed(random)),
        C = new(Signed(random), Signed(random), Signed(random)),
    };

    protected override double[] Components(ConformalCircle c) =>
        [c.NoE12, c.NoE13, c.NoE23, c.E123, c.NoE1Ni, c.NoE2Ni, c.NoE3Ni, c.E12Ni, c.E13Ni, c.E23Ni];

    protected override void RunGenerated(Vec3Triple[] inputs, ConformalCircle[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Generated(in inputs[i], out outputs[i]);
    }

    protected override void RunDirect(Vec3Triple[] inputs, ConformalCircle[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Direct(in inputs[i]);
    }

    protected override void RunHand(Vec3Triple[] inputs, ConformalCircle[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Hand(in inputs[i], out outputs[i]);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Generated(in Vec3Triple x, out ConformalCircle c)
    {
        #region GMac : CircleThroughPoints
        //GMac.Bind("p1", "ConformalPoint3D", "x.A");
        //GMac.Bind("p2", "ConformalPoint3D", "x.B");
        //GMac.Bind("p3", "ConformalPoint3D", "x.C");
        //GMac.Bind("phi.no^e1^e2", "<c.NoE12>");
        //GMac.Bind("phi.no^e1^e3", "<c.NoE13>");
        //GMac.Bind("phi.no^e2^e3", "<c.NoE23>");
        //GMac.Bind("phi.e1^e2^e3", "<c.E123>");
        //GMac.Bind("phi.no^e1^ni", "<c.NoE1Ni>");
        //GMac.Bind("phi.no^e2^ni", "<c.NoE2Ni>");
        //GMac.Bind("phi.no^e3^ni", "<c.NoE3Ni>");
        //GMac.Bind("phi.e1^e2^ni", "<c.E12Ni>");
        //GMac.Bind("phi.e1^e3^ni", "<c.E13Ni>");
        //GMac.Bind("phi.e2^e3^ni", "<c.E23Ni>");
        double tmp15 = x.A.x;
        double tmp0 = tmp15 - x.C.x;
        double tmp16 = x.A.y;
        double tmp1 = tmp16 - x.C.y;
        double tmp17 = x.A.z;
        double tmp2 = tmp17 - x.C.z;
        double tmp3 = -0.5 * (tmp0 * (tmp15 + x.C.x) + tmp1 * (tmp16 + x.C.y) + tmp2 * (tmp17 + x.C.z));
        double tmp4 = tmp15 - x.B.x;
        double tmp5 = x.B.y - tmp16;
        double tmp6 = x.B.z - tmp17;
        double tmp7 = 0.5 * (tmp5 * (tmp16 + x.B.y) + tmp6 * (tmp17 + x.B.z) - tmp4 * (tmp15 + x.B.x));
        double tmp8 = tmp1 * tmp4 + tmp0 * tmp5;
        double tmp9 = tmp2 * tmp4 + tmp0 * tmp6;
        double tmp10 = tmp1 * tmp6 - tmp2 * tmp5;
        double tmp11 = tmp0 * tmp7 - tmp3 * tmp4;
        double tmp12 = tmp1 * tmp7 + tmp3 * tmp5;
        double tmp13 = tmp2 * tmp7 + tmp3 * tmp6;
        c.NoE12 = tmp8;
        c.NoE13 = tmp9;
        c.NoE23 = tmp10;
        c.E123 = tmp10 * tmp15 + tmp8 * tmp17 - tmp9 * tmp16;
        c.NoE1Ni = tmp11;
        c.NoE2Ni = tmp12;
        c.NoE3Ni = tmp13;
        double tmp14 = 0.5 * (tmp17 * tmp17 + tmp16 * tmp16 + tmp15 * tmp15);
        c.E12Ni = tmp8 * tmp14 + tmp12 * tmp15 - tmp11 * tmp16;
        c.E13Ni = tmp9 * tmp14 + tmp13 * tmp15 - tmp11 * tmp17;
        c.E23Ni = tmp10 * tmp14 + tmp13 * tmp16 - tmp12 * tmp17;
        #endregion
    }

    public static ConformalCircle Direct(in Vec3Triple x)
    {
        var phi = Point(x.A).Op(Point(x.B)).Op(Point(x.C));
        return new ConformalCircle
        {
            NoE12 = phi["no^e1^e2"], NoE13 = phi["no^e1^e3"], NoE23 = phi["no^e2^e3"], E123 = phi["e1^e2^e3"],
            NoE1Ni = phi["no^e1^ni"], NoE2Ni = phi["no^e2^ni"], NoE3Ni = phi["no^e3^ni"],
            E12Ni = phi["e1^e2^ni"], E13Ni = phi["e1^e3^ni"], E23Ni = phi["e2^e3^ni"],
        };
    }

    /// <summary>
    /// p ∧ (q − p + α ni) ∧ (r − p + β ni) with a = q − p, b = r − p, α = ½(|q|² − |p|²) = ½ a·(p + q)
    /// and β likewise: no ∧ (a ∧ b) + no ∧ c ∧ ni + p ∧ a ∧ b + (p ∧ c + ½|p|² a ∧ b) ∧ ni, c = β a − α b.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Hand(in Vec3Triple x, out ConformalCircle c)
    {
        ref readonly var p = ref x.A;
        double ax = x.B.x - p.x, ay = x.B.y - p.y, az = x.B.z - p.z;
        double bx = x.C.x - p.x, by = x.C.y - p.y, bz = x.C.z - p.z;
        var alpha = 0.5 * (ax * (p.x + x.B.x) + ay * (p.y + x.B.y) + az * (p.z + x.B.z));
        var beta = 0.5 * (bx * (p.x + x.C.x) + by * (p.y + x.C.y) + bz * (p.z + x.C.z));
        var pi = 0.5 * (p.x * p.x + p.y * p.y + p.z * p.z);
        double ab12 = ax * by - ay * bx, ab13 = ax * bz - az * bx, ab23 = ay * bz - az * by;
        double cx = beta * ax - alpha * bx, cy = beta * ay - alpha * by, cz = beta * az - alpha * bz;
        c.NoE12 = ab12;
        c.NoE13 = ab13;
        c.NoE23 = ab23;
        c.E123 = p.x * ab23 - p.y * ab13 + p.z * ab12;
        c.NoE1Ni = cx;
        c.NoE2Ni = cy;
        c.NoE3Ni = cz;
        c.E12Ni = p.x * cy - p.y * cx + pi * ab12;
        c.E13Ni = p.x * cz - p.z * cx + pi * ab13;
        c.E23Ni = p.y * cz - p.z * cy + pi * ab23;
    }
}
