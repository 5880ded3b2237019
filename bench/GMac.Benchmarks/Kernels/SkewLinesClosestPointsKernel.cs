using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>(7.13) line parameters of the closest points of two skew lines Pᵢ + tᵢ Dᵢ.</summary>
public sealed class SkewLinesClosestPointsKernel : GaKernel<LinePair, LineParameters>
{
    public override string MacroName => "SkewLinesClosestPoints";
    public override string Source => "thesis (7.13)";

    /// <summary>
    /// Counted by hand: D = P2 − P1 (3 add), five dot products (15 mul, 10 add), ac − b² (2 mul, 1 add),
    /// its reciprocal (1 div), two numerators (4 mul, 2 add) and two scalings (2 mul).
    /// </summary>
    public override OperationCount HandOperations => new(Additions: 16, Multiplications: 23, Divisions: 1, Calls: 0);

    protected override LinePair CreateInput(Random random) => new()
    {
        P1 = new(Signed(random), Signed(random), Signed(random)),
        D1 = new(Signed(random) + 2, Signed(random), Signed(random)),
        P2 = new(Signed(random), Signed(random), Signed(random)),
        D2 = new(Signed(random), Signed(random) + 2, Signed(random)),
    };

    protected override double[] Components(LineParameters t) => [t.T1, t.T2];

    protected override void RunGenerated(LinePair[] inputs, LineParameters[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Generated(in inputs[i], out outputs[i]);
    }

    protected override void RunDirect(LinePair[] inputs, LineParameters[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Direct(in inputs[i]);
    }

    protected override void RunHand(LinePair[] inputs, LineParameters[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Hand(in inputs[i], out outputs[i]);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Generated(in LinePair l, out LineParameters t)
    {
        #region GMac : SkewLinesClosestPoints
        //GMac.Bind("p1", "Vector3D", "l.P1");
        //GMac.Bind("d1", "Vector3D", "l.D1");
        //GMac.Bind("p2", "Vector3D", "l.P2");
        //GMac.Bind("d2", "Vector3D", "l.D2");
        //GMac.Bind("t1.1", "<t.T1>");
        //GMac.Bind("t2.1", "<t.T2>");
        double tmp10 = l.D1.x;
        double tmp11 = l.D1.y;
        double tmp0 = l.D2.y * tmp10 - tmp11 * l.D2.x;
        double tmp12 = l.D1.z;
        double tmp1 = l.D2.z * tmp10 - tmp12 * l.D2.x;
        double tmp2 = l.D2.z * tmp11 - l.D2.y * tmp12;
        double tmp3 = tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2;
        double tmp4 = l.P2.x - l.P1.x;
        double tmp5 = l.P2.y - l.P1.y;
        double tmp6 = l.P2.z - l.P1.z;
        double tmp7 = tmp4 * tmp0 - tmp2 * tmp6;
        double tmp8 = tmp6 * tmp1 + tmp5 * tmp0;
        double tmp9 = tmp2 * tmp5 + tmp4 * tmp1;
        t.T1 = (l.D2.y * tmp7 + l.D2.z * tmp9 - l.D2.x * tmp8) / tmp3;
        t.T2 = (tmp11 * tmp7 + tmp12 * tmp9 - tmp10 * tmp8) / tmp3;
        #endregion
    }

    public static LineParameters Direct(in LinePair l)
    {
        var d1 = Of(l.D1);
        var d2 = Of(l.D2);
        var d = Of(l.P2) - Of(l.P1);
        var i = d1.Op(d2).Inverse();
        return new LineParameters { T1 = d2.Lcp(i).Lcp(d).ScalarPart, T2 = d1.Lcp(i).Lcp(d).ScalarPart };
    }

    /// <summary>The textbook normal equations of min |P1 + t1 D1 − P2 − t2 D2|²; t2 comes out with the sign of (7.13).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Hand(in LinePair l, out LineParameters t)
    {
        ref readonly var u = ref l.D1;
        ref readonly var v = ref l.D2;
        double dx = l.P2.x - l.P1.x, dy = l.P2.y - l.P1.y, dz = l.P2.z - l.P1.z;
        var a = u.x * u.x + u.y * u.y + u.z * u.z;
        var b = u.x * v.x + u.y * v.y + u.z * v.z;
        var c = v.x * v.x + v.y * v.y + v.z * v.z;
        var e1 = u.x * dx + u.y * dy + u.z * dz;
        var e2 = v.x * dx + v.y * dy + v.z * dz;
        var inverse = 1 / (a * c - b * b);
        t.T1 = (c * e1 - b * e2) * inverse;
        t.T2 = (b * e1 - a * e2) * inverse;
    }
}
