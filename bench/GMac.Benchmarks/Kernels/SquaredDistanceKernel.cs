using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>(3.72) the squared distance d² = −2 p⌋q of two normalized conformal points.</summary>
public sealed class SquaredDistanceKernel : GaKernel<Vec3Pair, double>
{
    public override string MacroName => "SquaredDistance";
    public override string Source => "thesis (3.72)";

    /// <summary>Counted by hand: 3 differences, 3 squares, 2 additions.</summary>
    public override OperationCount HandOperations => new(Additions: 5, Multiplications: 3, Divisions: 0, Calls: 0);

    protected override Vec3Pair CreateInput(Random random) => new()
    {
        U = new(Signed(random), Signed(random), Signed(random)),
        V = new(Signed(random), Signed(random), Signed(random)),
    };

    protected override double[] Components(double value) => [value];

    protected override void RunGenerated(Vec3Pair[] inputs, double[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Generated(in inputs[i], out outputs[i]);
    }

    protected override void RunDirect(Vec3Pair[] inputs, double[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Direct(in inputs[i]);
    }

    protected override void RunHand(Vec3Pair[] inputs, double[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Hand(in inputs[i]);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Generated(in Vec3Pair x, out double d2)
    {
        #region GMac : SquaredDistance
        //GMac.Bind("p", "ConformalPoint3D", "x.U");
        //GMac.Bind("q", "ConformalPoint3D", "x.V");
        //GMac.Bind("d2.1", "<d2>");
        double tmp0 = x.V.x - x.U.x;
        double tmp1 = x.V.y - x.U.y;
        double tmp2 = x.V.z - x.U.z;
        d2 = tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2;
        #endregion
    }

    public static double Direct(in Vec3Pair x) => -2 * Point(x.U).Lcp(Point(x.V)).ScalarPart;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double Hand(in Vec3Pair x)
    {
        double dx = x.U.x - x.V.x, dy = x.U.y - x.V.y, dz = x.U.z - x.V.z;
        return dx * dx + dy * dy + dz * dz;
    }
}
