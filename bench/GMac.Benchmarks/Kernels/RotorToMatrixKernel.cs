using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>(7.4) the columns vᵢ = R eᵢ R~ of the rotation matrix of a unit rotor.</summary>
public sealed class RotorToMatrixKernel : GaKernel<Rotor3, Vec3Triple>
{
    public override string MacroName => "RotorToMatrix";
    public override string Source => "thesis (7.4)-(7.7)";

    /// <summary>Counted by hand: doubled coordinates (3 add), nine products, three diagonals (6 add), six off-diagonals (6 add).</summary>
    public override OperationCount HandOperations => new(Additions: 15, Multiplications: 9, Divisions: 0, Calls: 0);

    protected override Rotor3 CreateInput(Random random)
    {
        double w, x, y, z, n;
        do
        {
            (w, x, y, z) = (Signed(random), Signed(random), Signed(random), Signed(random));
            n = Math.Sqrt(w * w + x * x + y * y + z * z);
        } while (n < 0.1 || n > 1);
        return new Rotor3(w / n, x / n, y / n, z / n);
    }

    protected override double[] Components(Vec3Triple m) => [m.A.x, m.A.y, m.A.z, m.B.x, m.B.y, m.B.z, m.C.x, m.C.y, m.C.z];

    protected override void RunGenerated(Rotor3[] inputs, Vec3Triple[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Generated(in inputs[i], out outputs[i]);
    }

    protected override void RunDirect(Rotor3[] inputs, Vec3Triple[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Direct(in inputs[i]);
    }

    protected override void RunHand(Rotor3[] inputs, Vec3Triple[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Hand(in inputs[i], out outputs[i]);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Generated(in Rotor3 q, out Vec3Triple m)
    {
        #region GMac : RotorToMatrix
        //GMac.Bind("r.1", "<q.w>");
        //GMac.Bind("r.e2^e3", "<q.x>");
        //GMac.Bind("r.e3^e1", "<q.y>");
        //GMac.Bind("r.e1^e2", "<q.z>");
        //GMac.Bind("c1", "Vector3D", "m.A");
        //GMac.Bind("c2", "Vector3D", "m.B");
        //GMac.Bind("c3", "Vector3D", "m.C");
        double tmp13 = q.x;
        double tmp0 = tmp13 + tmp13;
        double tmp14 = q.y;
        double tmp1 = tmp14 + tmp14;
        double tmp2 = q.z + q.z;
        double tmp3 = q.z * tmp2;
        double tmp4 = tmp14 * tmp1;
        double tmp5 = tmp13 * tmp1;
        double tmp12 = q.w;
        double tmp6 = tmp12 * tmp2;
        m.A.x = 1.0 - tmp4 - tmp3;
        m.A.y = tmp5 - tmp6;
        double tmp7 = tmp13 * tmp2;
        double tmp8 = tmp12 * tmp1;
        m.A.z = tmp8 + tmp7;
        m.B.x = tmp6 + tmp5;
        double tmp9 = tmp13 * tmp0;
        m.B.y = 1.0 - tmp9 - tmp3;
        double tmp10 = tmp14 * tmp2;
        double tmp11 = tmp12 * tmp0;
        m.B.z = tmp10 - tmp11;
        m.C.x = tmp7 - tmp8;
        m.C.y = tmp11 + tmp10;
        m.C.z = 1.0 - tmp9 - tmp4;
        #endregion
    }

    public static Vec3Triple Direct(in Rotor3 q)
    {
        var r = Of(q);
        var rr = r.Reverse();
        return new Vec3Triple { A = ToVec3(r.Gp(E3e1).Gp(rr)), B = ToVec3(r.Gp(E3e2).Gp(rr)), C = ToVec3(r.Gp(E3e3).Gp(rr)) };
    }

    /// <summary>(7.6) with the diagonal corrected to 1 − 2(y² + z²) and its companions.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Hand(in Rotor3 q, out Vec3Triple m)
    {
        double x2 = q.x + q.x, y2 = q.y + q.y, z2 = q.z + q.z;
        double xx = q.x * x2, yy = q.y * y2, zz = q.z * z2;
        double xy = q.x * y2, xz = q.x * z2, yz = q.y * z2;
        double wx = q.w * x2, wy = q.w * y2, wz = q.w * z2;
        m.A.x = 1 - (yy + zz);
        m.A.y = xy - wz;
        m.A.z = xz + wy;
        m.B.x = xy + wz;
        m.B.y = 1 - (xx + zz);
        m.B.z = yz - wx;
        m.C.x = xz - wy;
        m.C.y = yz + wx;
        m.C.z = 1 - (xx + yy);
    }
}
