using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>(7.2) Gram-Schmidt by contractions: w1 = v1, w2 = v1⌋(v1^v2), w3 = (v1^v2)⌋(v1^v2^v3).</summary>
public sealed class GramSchmidtContractionKernel : GaKernel<Vec3Triple, Vec3Triple>
{
    public override string MacroName => "GramSchmidtContraction";
    public override string Source => "thesis (7.2)";

    /// <summary>Counted by hand: n = v1×v2 and w2 = n×v1 (12 mul, 6 add), det = n·v3 (3 mul, 2 add), w3 = −det n (3 mul).</summary>
    public override OperationCount HandOperations => new(Additions: 8, Multiplications: 18, Divisions: 0, Calls: 0);

    protected override Vec3Triple CreateInput(Random random) => new()
    {
        A = new(Signed(random), Signed(random), Signed(random)),
        B = new(Signed(random), Signed(random), Signed(random)),
        C = new(Signed(random), Signed(random), Signed(random)),
    };

    protected override double[] Components(Vec3Triple w) => [w.A.x, w.A.y, w.A.z, w.B.x, w.B.y, w.B.z, w.C.x, w.C.y, w.C.z];

    protected override void RunGenerated(Vec3Triple[] inputs, Vec3Triple[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Generated(in inputs[i], out outputs[i]);
    }

    protected override void RunDirect(Vec3Triple[] inputs, Vec3Triple[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Direct(in inputs[i]);
    }

    protected override void RunHand(Vec3Triple[] inputs, Vec3Triple[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Hand(in inputs[i], out outputs[i]);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Generated(in Vec3Triple v, out Vec3Triple w)
    {
        #region GMac : GramSchmidtContraction
        //GMac.Bind("v1", "Vector3D", "v.A");
        //GMac.Bind("v2", "Vector3D", "v.B");
        //GMac.Bind("v3", "Vector3D", "v.C");
        //GMac.Bind("w1", "Vector3D", "w.A");
        //GMac.Bind("w2", "Vector3D", "w.B");
        //GMac.Bind("w3", "Vector3D", "w.C");
        double tmp4 = v.A.x;
        double tmp5 = v.A.y;
        double tmp0 = tmp5 * v.B.x - tmp4 * v.B.y;
        double tmp6 = v.A.z;
        double tmp1 = tmp4 * v.B.z - tmp6 * v.B.x;
        double tmp2 = tmp6 * v.B.y - tmp5 * v.B.z;
        double tmp3 = -(tmp0 * v.C.z) - tmp2 * v.C.x - tmp1 * v.C.y;
        w.A.x = tmp4;
        w.A.y = tmp5;
        w.A.z = tmp6;
        w.B.x = tmp0 * tmp5 - tmp1 * tmp6;
        w.B.y = tmp2 * tmp6 - tmp0 * tmp4;
        w.B.z = tmp1 * tmp4 - tmp2 * tmp5;
        w.C.x = tmp2 * tmp3;
        w.C.y = tmp1 * tmp3;
        w.C.z = tmp0 * tmp3;
        #endregion
    }

    public static Vec3Triple Direct(in Vec3Triple v)
    {
        var v1 = Of(v.A);
        var v2 = Of(v.B);
        var v3 = Of(v.C);
        var b = v1.Op(v2);
        return new Vec3Triple { A = ToVec3(v1), B = ToVec3(v1.Lcp(b)), C = ToVec3(b.Lcp(b.Op(v3))) };
    }

    /// <summary>v1⌋(v1^v2) = (v1×v2)×v1, and (v1^v2)⌋(det I3) = −det (v1×v2).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Hand(in Vec3Triple v, out Vec3Triple w)
    {
        ref readonly var a = ref v.A;
        ref readonly var b = ref v.B;
        ref readonly var c = ref v.C;
        var nx = a.y * b.z - a.z * b.y;
        var ny = a.z * b.x - a.x * b.z;
        var nz = a.x * b.y - a.y * b.x;
        var det = nx * c.x + ny * c.y + nz * c.z;
        w.A = a;
        w.B.x = ny * a.z - nz * a.y;
        w.B.y = nz * a.x - nx * a.z;
        w.B.z = nx * a.y - ny * a.x;
        w.C.x = -det * nx;
        w.C.y = -det * ny;
        w.C.z = -det * nz;
    }
}
