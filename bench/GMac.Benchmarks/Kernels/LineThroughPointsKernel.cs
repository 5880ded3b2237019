using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>(3.83) the line through two points, p ∧ q ∧ ni: direction q − p and moment p × q.</summary>
public sealed class LineThroughPointsKernel : GaKernel<Vec3Pair, ConformalLine>
{
    public override string MacroName => "LineThroughPoints";
    public override string Source => "thesis (3.83)";

    /// <summary>Counted by hand: d = q − p (3 add), the moment p × d (6 mul, 3 add).</summary>
    public override OperationCount HandOperations => new(Additions: 6, Multiplications: 6, Divisions: 0, Calls: 0);

    protected override Vec3Pair CreateInput(Random random) => new()
    {
        U = new(Signed(random), Signed(random), Signed(random)),
        V = new(Signed(random), Signed(random), Signed(random)),
    };

    protected override double[] Components(ConformalLine l) => [l.Direction.x, l.Direction.y, l.Direction.z, l.E12Ni, l.E13Ni, l.E23Ni];

    protected override void RunGenerated(Vec3Pair[] inputs, ConformalLine[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Generated(in inputs[i], out outputs[i]);
    }

    protected override void RunDirect(Vec3Pair[] inputs, ConformalLine[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Direct(in inputs[i]);
    }

    protected override void RunHand(Vec3Pair[] inputs, ConformalLine[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Hand(in inputs[i], out outputs[i]);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Generated(in Vec3Pair x, out ConformalLine l)
    {
        #region GMac : LineThroughPoints
        //GMac.Bind("p1", "ConformalPoint3D", "x.U");
        //GMac.Bind("p2", "ConformalPoint3D", "x.V");
        //GMac.Bind("line.no^e1^ni", "<l.Direction.x>");
        //GMac.Bind("line.no^e2^ni", "<l.Direction.y>");
        //GMac.Bind("line.no^e3^ni", "<l.Direction.z>");
        //GMac.Bind("line.e1^e2^ni", "<l.E12Ni>");
        //GMac.Bind("line.e1^e3^ni", "<l.E13Ni>");
        //GMac.Bind("line.e2^e3^ni", "<l.E23Ni>");
        double tmp3 = x.U.x;
        double tmp0 = x.V.x - tmp3;
        double tmp4 = x.U.y;
        double tmp1 = x.V.y - tmp4;
        double tmp5 = x.U.z;
        double tmp2 = x.V.z - tmp5;
        l.Direction.x = tmp0;
        l.Direction.y = tmp1;
        l.Direction.z = tmp2;
        l.E12Ni = tmp1 * tmp3 - tmp0 * tmp4;
        l.E13Ni = tmp2 * tmp3 - tmp0 * tmp5;
        l.E23Ni = tmp2 * tmp4 - tmp1 * tmp5;
        #endregion
    }

    public static ConformalLine Direct(in Vec3Pair x)
    {
        var line = Point(x.U).Op(Point(x.V)).Op(CgaNi);
        return new ConformalLine
        {
            Direction = new(line["no^e1^ni"], line["no^e2^ni"], line["no^e3^ni"]),
            E12Ni = line["e1^e2^ni"], E13Ni = line["e1^e3^ni"], E23Ni = line["e2^e3^ni"],
        };
    }

    /// <summary>The moment as p × (q − p): the products of the large coordinates never cancel.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Hand(in Vec3Pair x, out ConformalLine l)
    {
        ref readonly var p = ref x.U;
        double dx = x.V.x - p.x, dy = x.V.y - p.y, dz = x.V.z - p.z;
        l.Direction = new(dx, dy, dz);
        l.E23Ni = p.y * dz - p.z * dy;
        l.E13Ni = p.x * dz - p.z * dx;
        l.E12Ni = p.x * dy - p.y * dx;
    }
}
