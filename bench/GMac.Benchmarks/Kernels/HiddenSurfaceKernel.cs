using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>(7.1) hidden surface removal: the signed area ⟨(v3 − v1) ^ (v2 − v1)⟩ of a projected triangle.</summary>
public sealed class HiddenSurfaceKernel : GaKernel<Vec2Triple, double>
{
    public override string MacroName => "HiddenSurface";
    public override string Source => "thesis (7.1)";

    /// <summary>Counted by hand: 5 subtractions, 2 products.</summary>
    public override OperationCount HandOperations => new(Additions: 5, Multiplications: 2, Divisions: 0, Calls: 0);

    protected override Vec2Triple CreateInput(Random random) => new()
    {
        A = new(Signed(random), Signed(random)),
        B = new(Signed(random), Signed(random)),
        C = new(Signed(random), Signed(random)),
    };

    protected override double[] Components(double value) => [value];

    protected override void RunGenerated(Vec2Triple[] inputs, double[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Generated(in inputs[i], out outputs[i]);
    }

    protected override void RunDirect(Vec2Triple[] inputs, double[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Direct(in inputs[i]);
    }

    protected override void RunHand(Vec2Triple[] inputs, double[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Hand(in inputs[i]);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Generated(in Vec2Triple t, out double s)
    {
        #region GMac : HiddenSurface
        //GMac.Bind("v1.e1", "<t.A.x>");
        //GMac.Bind("v1.e2", "<t.A.y>");
        //GMac.Bind("v2.e1", "<t.B.x>");
        //GMac.Bind("v2.e2", "<t.B.y>");
        //GMac.Bind("v3.e1", "<t.C.x>");
        //GMac.Bind("v3.e2", "<t.C.y>");
        //GMac.Bind("s.1", "<s>");
        s = (t.C.x - t.A.x) * (t.B.y - t.A.y) - (t.B.x - t.A.x) * (t.C.y - t.A.y);
        #endregion
    }

    public static double Direct(in Vec2Triple t)
    {
        var v1 = Of(t.A);
        var v2 = Of(t.B);
        var v3 = Of(t.C);
        return (v3 - v1).Op(v2 - v1)["e1^e2"];
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double Hand(in Vec2Triple t) =>
        (t.C.x - t.A.x) * (t.B.y - t.A.y) - (t.C.y - t.A.y) * (t.B.x - t.A.x);
}
