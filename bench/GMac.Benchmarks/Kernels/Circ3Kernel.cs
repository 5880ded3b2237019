using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>Table 7-1 circ3: v = 4(c1² + c2² − 1) c1 e1 + 4(c1² + c2² − 1) c2 e2 + 2 c3 e3, cᵢ = p⌋eᵢ.</summary>
public sealed class Circ3Kernel : GaKernel<Vec3, Vec3>
{
    public override string MacroName => "Circ3";
    public override string Source => "thesis Table 7-1";

    /// <summary>Counted by hand: x², y², 4·(…), t·x, t·y, 2·z (6 mul) and x² + y² − 1 (2 add).</summary>
    public override OperationCount HandOperations => new(Additions: 2, Multiplications: 6, Divisions: 0, Calls: 0);

    protected override Vec3 CreateInput(Random random) => new(Signed(random), Signed(random), Signed(random));

    protected override double[] Components(Vec3 v) => [v.x, v.y, v.z];

    protected override void RunGenerated(Vec3[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Generated(in inputs[i], out outputs[i]);
    }

    protected override void RunDirect(Vec3[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Direct(in inputs[i]);
    }

    protected override void RunHand(Vec3[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Hand(in inputs[i], out outputs[i]);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Generated(in Vec3 p, out Vec3 v)
    {
        #region GMac : Circ3
        //GMac.Bind("p", "Vector3D", "p");
        //GMac.Bind("v.e1", "<v.x>");
        //GMac.Bind("v.e2", "<v.y>");
        //GMac.Bind("v.e3", "<v.z>");
        double tmp1 = p.y;
        double tmp0 = 4.0 * (tmp1 * tmp1 + p.x * p.x - 1.0);
        double tmp2 = p.z;
        v.x = p.x * tmp0;
        v.y = tmp1 * tmp0;
        v.z = 2.0 * tmp2;
        #endregion
    }

    public static Vec3 Direct(in Vec3 point)
    {
        var p = Of(point);
        var c1 = p.Lcp(E3e1).ScalarPart;
        var c2 = p.Lcp(E3e2).ScalarPart;
        var c3 = p.Lcp(E3e3).ScalarPart;
        var v = 4 * (c1 * c1 + c2 * c2 - 1) * c1 * E3e1 + 4 * (c1 * c1 + c2 * c2 - 1) * c2 * E3e2 + 2 * c3 * E3e3;
        return ToVec3(v);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Hand(in Vec3 p, out Vec3 v)
    {
        var t = 4 * (p.x * p.x + p.y * p.y - 1);
        v.x = t * p.x;
        v.y = t * p.y;
        v.z = 2 * p.z;
    }
}
