using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>Table 7-1 vortexS: v = ω (p⌋a) a⁻¹ + γ [(p^a) a⁻¹][a⌋I3].</summary>
public sealed class VortexSKernel : GaKernel<VortexInput, Vec3>
{
    public override string MacroName => "VortexS";
    public override string Source => "thesis Table 7-1";

    /// <summary>Counted by hand: a·a, p·a (6 mul, 4 add), 1/a·a, ω(p·a)/a² (2 mul), a×p (6 mul, 3 add), γ·, k· (6 mul), sum (3 add).</summary>
    public override OperationCount HandOperations => new(Additions: 10, Multiplications: 20, Divisions: 1, Calls: 0);

    protected override VortexInput CreateInput(Random random) => new()
    {
        P = new(Signed(random), Signed(random), Signed(random)),
        A = new(Signed(random) + 2, Signed(random), Signed(random)),
        Omega = Signed(random),
        Gamma = Signed(random),
    };

    protected override double[] Components(Vec3 v) => [v.x, v.y, v.z];

    protected override void RunGenerated(VortexInput[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Generated(in inputs[i], out outputs[i]);
    }

    protected override void RunDirect(VortexInput[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Direct(in inputs[i]);
    }

    protected override void RunHand(VortexInput[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Hand(in inputs[i], out outputs[i]);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Generated(in VortexInput x, out Vec3 v)
    {
        #region GMac : VortexS
        //GMac.Bind("p", "Vector3D", "x.P");
        //GMac.Bind("a", "Vector3D", "x.A");
        //GMac.Bind("omega.1", "<x.Omega>");
        //GMac.Bind("gamma.1", "<x.Gamma>");
        //GMac.Bind("v", "Vector3D", "v");
        double tmp1 = x.P.x;
        double tmp2 = x.P.y;
        double tmp3 = x.P.z;
        double tmp4 = x.A.x;
        double tmp5 = x.A.y;
        double tmp6 = x.A.z;
        double tmp0 = x.Omega * (tmp6 * tmp3 + tmp5 * tmp2 + tmp4 * tmp1) / (tmp4 * tmp4 + tmp5 * tmp5 + tmp6 * tmp6);
        double tmp7 = x.Gamma;
        v.x = tmp4 * tmp0 + tmp7 * (tmp3 * tmp5 - tmp2 * tmp6);
        v.y = tmp5 * tmp0 + tmp7 * (tmp1 * tmp6 - tmp3 * tmp4);
        v.z = tmp6 * tmp0 + tmp7 * (tmp2 * tmp4 - tmp1 * tmp5);
        #endregion
    }

    public static Vec3 Direct(in VortexInput x)
    {
        var p = Of(x.P);
        var a = Of(x.A);
        var ai = a.Inverse();
        var v = x.Omega * p.Lcp(a).Gp(ai) + x.Gamma * p.Op(a).Gp(ai).Gp(a.Lcp(E3I));
        return ToVec3(v.Grade(1));
    }

    /// <summary>(p^a) a⁻¹ is the rejection of p from a, and its product with the dual plane a I3 is a × p.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Hand(in VortexInput x, out Vec3 v)
    {
        ref readonly var p = ref x.P;
        ref readonly var a = ref x.A;
        var k = x.Omega * (p.x * a.x + p.y * a.y + p.z * a.z) / (a.x * a.x + a.y * a.y + a.z * a.z);
        var g = x.Gamma;
        v.x = k * a.x + g * (a.y * p.z - a.z * p.y);
        v.y = k * a.y + g * (a.z * p.x - a.x * p.z);
        v.z = k * a.z + g * (a.x * p.y - a.y * p.x);
    }
}
