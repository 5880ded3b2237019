using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>(7.9) fifth-degree Julia step x ← x e x e x e x e x + c.</summary>
public sealed class JuliaStep5Kernel : GaKernel<Vec2Pair, Vec2>
{
    public override string MacroName => "JuliaStep5";
    public override string Source => "thesis (7.9)";

    /// <summary>Counted by hand, as z⁵ + c: a², b², a⁴, b⁴, 10a²b² (2), 5b⁴, 5a⁴, a·(…), b·(…) (10 mul), 4 sums and + c (6 add).</summary>
    public override OperationCount HandOperations => new(Additions: 6, Multiplications: 10, Divisions: 0, Calls: 0);

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
        #region GMac : JuliaStep5
        //GMac.Bind("x.e1", "<j.X.x>");
        //GMac.Bind("x.e2", "<j.X.y>");
        //GMac.Bind("c.e1", "<j.C.x>");
        //GMac.Bind("c.e2", "<j.C.y>");
        //GMac.Bind("y.e1", "<y.x>");
        //GMac.Bind("y.e2", "<y.y>");
        double tmp4 = j.X.y;
        double tmp0 = tmp4 * tmp4;
        double tmp1 = 10.0 * tmp0;
        double tmp2 = j.X.x * j.X.x;
        double tmp3 = tmp0 * tmp0;
        double tmp5 = j.C.y;
        y.x = j.X.x * ((tmp2 - tmp1) * tmp2 + 5.0 * tmp3) + j.C.x;
        y.y = tmp4 * ((5.0 * tmp2 - tmp1) * tmp2 + tmp3) + tmp5;
        #endregion
    }

    public static Vec2 Direct(in Vec2Pair j)
    {
        var x = Of(j.X);
        var xe = x.Gp(E2e1);
        return ToVec2(xe.Gp(xe).Gp(xe).Gp(xe).Gp(x) + Of(j.C));
    }

    /// <summary>The coordinates of z⁵ = (a + b i)⁵ by the binomial expansion.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Hand(in Vec2Pair j, out Vec2 y)
    {
        double a = j.X.x, b = j.X.y;
        double aa = a * a, bb = b * b;
        double a4 = aa * aa, b4 = bb * bb, m = 10 * aa * bb;
        y.x = a * (a4 - m + 5 * b4) + j.C.x;
        y.y = b * (5 * a4 - m + b4) + j.C.y;
    }
}
