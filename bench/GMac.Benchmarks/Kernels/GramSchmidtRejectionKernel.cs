using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>(7.3) Gram-Schmidt by rejections: w2 = (v2^w1) w1⁻¹, w3 = (v3^w1^w2)(w1^w2)⁻¹.</summary>
public sealed class GramSchmidtRejectionKernel : GaKernel<Vec3Triple, Vec3Triple>
{
    public override string MacroName => "GramSchmidtRejection";
    public override string Source => "thesis (7.3)";

    /// <summary>
    /// Counted by hand: v1·v1, v1·v2 (6 mul, 4 add), k = quotient (1 div), w2 = v2 − k v1 (3 mul, 3 add),
    /// n = v1×v2 (6 mul, 3 add), v3·n and n·n (6 mul, 4 add), s = quotient (1 div), w3 = s n (3 mul).
    /// </summary>
    public override OperationCount HandOperations => new(Additions: 14, Multiplications: 24, Divisions: 2, Calls: 0);

    protected override Vec3Triple CreateInput(Random random) => new()
    {
        A = new(Signed(random) + 2, Signed(random), Signed(random)),
        B = new(Signed(random), Signed(random) + 2, Signed(random)),
        C = new(Signed(random), Signed(random), Signed(random) + 2),
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
        #region GMac : GramSchmidtRejection
        //GMac.Bind("v1", "Vector3D", "v.A");
        //GMac.Bind("v2", "Vector3D", "v.B");
        //GMac.Bind("v3", "Vector3D", "v.C");
        //GMac.Bind("w1", "Vector3D", "w.A");
        //GMac.Bind("w2", "Vector3D", "w.B");
        //GMac.Bind("w3", "Vector3D", "w.C");
        double tmp9 = v.A.y;
        double tmp12 = v.B.y;
        double tmp0 = tmp12 - tmp9;
        double tmp8 = v.A.x;
        double tmp11 = v.B.x;
        double tmp1 = tmp11 - tmp8;
        double tmp2 = tmp0 * tmp8 - tmp1 * tmp9;
        double tmp10 = v.A.z;
        double tmp13 = v.B.z;
        double tmp3 = tmp13 - tmp10;
        double tmp4 = tmp1 * tmp10 - tmp3 * tmp8;
        double tmp5 = tmp3 * tmp9 - tmp0 * tmp10;
        double tmp6 = (tmp8 * tmp11 + tmp9 * tmp12 + tmp10 * tmp13) / (tmp10 * tmp10 + tmp8 * tmp8 + tmp9 * tmp9);
        double tmp7 = (v.C.y * tmp4 + v.C.x * tmp5 + v.C.z * tmp2) / (tmp2 * tmp2 + tmp4 * tmp4 + tmp5 * tmp5);
        w.A.x = tmp8;
        w.A.y = tmp9;
        w.A.z = tmp10;
        w.B.x = tmp11 - tmp8 * tmp6;
        w.B.y = tmp12 - tmp9 * tmp6;
        w.B.z = tmp13 - tmp10 * tmp6;
        w.C.x = tmp5 * tmp7;
        w.C.y = tmp4 * tmp7;
        w.C.z = tmp2 * tmp7;
        #endregion
    }

    public static Vec3Triple Direct(in Vec3Triple v)
    {
        var v1 = Of(v.A);
        var v2 = Of(v.B);
        var v3 = Of(v.C);
        var w1 = v1;
        var w2 = v2.Op(w1).Gp(w1.Inverse());
        var w3 = v3.Op(w1).Op(w2).Gp(w1.Op(w2).Inverse());
        return new Vec3Triple { A = ToVec3(w1), B = ToVec3(w2), C = ToVec3(w3) };
    }

    /// <summary>w2 rejects v1 from v2; w3 is the part of v3 along the normal v1×v2 of the plane of w1, w2.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Hand(in Vec3Triple v, out Vec3Triple w)
    {
        ref readonly var a = ref v.A;
        ref readonly var b = ref v.B;
        ref readonly var c = ref v.C;
        var k = (a.x * b.x + a.y * b.y + a.z * b.z) / (a.x * a.x + a.y * a.y + a.z * a.z);
        w.A = a;
        w.B.x = b.x - k * a.x;
        w.B.y = b.y - k * a.y;
        w.B.z = b.z - k * a.z;
        var nx = a.y * b.z - a.z * b.y;
        var ny = a.z * b.x - a.x * b.z;
        var nz = a.x * b.y - a.y * b.x;
        var s = (c.x * nx + c.y * ny + c.z * nz) / (nx * nx + ny * ny + nz * nz);
        w.C.x = s * nx;
        w.C.y = s * ny;
        w.C.z = s * nz;
    }
}
