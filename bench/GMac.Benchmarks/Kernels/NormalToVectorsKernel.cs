using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>§4.10 the normal to two vectors, w = (u ^ v) ⌋ I3⁻¹.</summary>
public sealed class NormalToVectorsKernel : GaKernel<Vec3Pair, Vec3>
{
    private static readonly GMac.Core.Algebra.Multivector<double> InverseI3 = E3I.Inverse();

    public override string MacroName => "NormalToVectors";
    public override string Source => "thesis §4.10";

    /// <summary>Counted by hand: the cross product, 6 mul and 3 sub.</summary>
    public override OperationCount HandOperations => new(Additions: 3, Multiplications: 6, Divisions: 0, Calls: 0);

    protected override Vec3Pair CreateInput(Random random) => new()
    {
        U = new(Signed(random), Signed(random), Signed(random)),
        V = new(Signed(random), Signed(random), Signed(random)),
    };

    protected override double[] Components(Vec3 v) => [v.x, v.y, v.z];

    protected override void RunGenerated(Vec3Pair[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Generated(in inputs[i], out outputs[i]);
    }

    protected override void RunDirect(Vec3Pair[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Direct(in inputs[i]);
    }

    protected override void RunHand(Vec3Pair[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Hand(in inputs[i], out outputs[i]);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Generated(in Vec3Pair x, out Vec3 w)
    {
        #region GMac : NormalToVectors
        //GMac.Bind("u", "Vector3D", "x.U");
        //GMac.Bind("v", "Vector3D", "x.V");
        //GMac.Bind("w", "Vector3D", "w");
        double tmp0 = x.U.x;
        double tmp1 = x.U.y;
        double tmp2 = x.U.z;
        double tmp3 = x.V.x;
        double tmp4 = x.V.y;
        double tmp5 = x.V.z;
        w.x = tmp1 * tmp5 - tmp2 * tmp4;
        w.y = tmp2 * tmp3 - tmp0 * tmp5;
        w.z = tmp0 * tmp4 - tmp1 * tmp3;
        #endregion
    }

    public static Vec3 Direct(in Vec3Pair x) => ToVec3(Of(x.U).Op(Of(x.V)).Lcp(InverseI3));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Hand(in Vec3Pair x, out Vec3 w)
    {
        ref readonly var u = ref x.U;
        ref readonly var v = ref x.V;
        w.x = u.y * v.z - u.z * v.y;
        w.y = u.z * v.x - u.x * v.z;
        w.z = u.x * v.y - u.y * v.x;
    }
}
