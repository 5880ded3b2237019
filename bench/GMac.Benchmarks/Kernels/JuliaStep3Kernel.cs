using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>(7.8) third-degree Julia step x ← x e x e x + c.</summary>
public sealed class JuliaStep3Kernel : GaKernel<Vec2Pair, Vec2>
{
    public override string MacroName => "JuliaStep3";
    public override string Source => "thesis (7.8)";

    /// <summary>Counted by hand, as the complex cube z³ + c: a², b², 3b², 3a², a·(…), b·(…) (6 mul), 2 subtractions and + c (4 add).</summary>
    public override OperationCount HandOperations => new(Additions: 4, Multiplications: 6, Divisions: 0, Calls: 0);

    protected override Vec2Pair CreateInput(Random random) => new()
    {
        X = new(Signed(random), Signed(random)),
        C = new(Signed(random), Signed(random)),
    };

    protected override double[] Components(Vec2 v) => [v.x, v.y];

    protected override void RunGenerated(Vec2Pair[] inputs, Vec2[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Generated(in inputs[i], out outputs[i]);
    }

    protected override void RunDirect(Vec2Pair[] inputs, Vec2[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Direct(in inputs[i]);
    }

    protected override void RunHand(Vec2Pair[] inputs, Vec2[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Hand(in inputs[i], out outputs[i]);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Generated(in Vec2Pair j, out Vec2 y)
    {
        #region GMac : JuliaStep3
        //GMac.Bind("x.e1", "<j.X.x>");
        //GMac.Bind("x.e2", "<j.X.y>");
        //GMac.Bind("c.e1", "<j.C.x>");
        //GMac.Bind("c.e2", "<j.C.y>");
        //GMac.Bind("y.e1", "<y.x>");
        //GMac.Bind("y.e2", "<y.y>");
        double tmp2 = j.X.y;
        double tmp0 = tmp2 * tmp2;
        double tmp1 = j.X.x * j.X.x;
        double tmp3 = j.C.y;
        y.x = j.X.x * (tmp1 - 3.0 * tmp0) + j.C.x;
        y.y = tmp2 * (3.0 * tmp1 - tmp0) + tmp3;
        #endregion
    }

    public static Vec2 Direct(in Vec2Pair j)
    {
        var x = Of(j.X);
        var e = E2e1;
        return ToVec2(x.Gp(e).Gp(x).Gp(e).Gp(x) + Of(j.C));
    }

    /// <summary>x e is the complex number a − b i, so x e x e x has the coordinates of z³, z = a + b i.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Hand(in Vec2Pair j, out Vec2 y)
    {
        double a = j.X.x, b = j.X.y;
        double aa = a * a, bb = b * b;
        y.x = a * (aa - 3 * bb) + j.C.x;
        y.y = b * (3 * aa - bb) + j.C.y;
    }
}
