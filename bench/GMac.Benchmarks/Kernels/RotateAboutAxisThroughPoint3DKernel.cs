using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using GMac.Core.Algebra;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>(3.96): the general rotation V_p V_R V_p⁻¹ about the line through a point along an axis, applied to a point.</summary>
public sealed class RotateAboutAxisThroughPoint3DKernel : GaKernel<AxisRotationInput, Vec3>
{
    public override string MacroName => "RotateAboutAxisThroughPoint3D";
    public override string Source => "thesis (3.94), (3.96)";

    /// <summary>
    /// Counted by hand, Rodrigues' formula: |a|² (3 mul, 2 add), sqrt, 1/|a| (1 div), k = a/|a| (3 mul),
    /// cos, sin, u = x − o (3 add), k×u (6 mul, 3 add), k·u (3 mul, 2 add), (k·u)(1 − cos) (1 mul, 1 add),
    /// o + u cos + (k×u) sin + k f (9 mul, 9 add).
    /// </summary>
    public override OperationCount HandOperations => new(Additions: 20, Multiplications: 25, Divisions: 1, Calls: 3);

    protected override AxisRotationInput CreateInput(Random random) => new()
    {
        Axis = new(Signed(random) + 2, Signed(random), Signed(random)),
        Origin = new(Signed(random), Signed(random), Signed(random)),
        Angle = Signed(random) * Math.PI,
        Point = new(Signed(random), Signed(random), Signed(random)),
    };

    protected override double[] Components(Vec3 v) => [v.x, v.y, v.z];

    protected override void RunGenerated(AxisRotationInput[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Generated(in inputs[i], out outputs[i]);
    }

    protected override void RunDirect(AxisRotationInput[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Direct(in inputs[i]);
    }

    protected override void RunHand(AxisRotationInput[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Hand(in inputs[i], out outputs[i]);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Generated(in AxisRotationInput x, out Vec3 p)
    {
        #region GMac : RotateAboutAxisThroughPoint3D
        //GMac.Bind("axis", "Vector3D", "x.Axis");
        //GMac.Bind("origin", "Vector3D", "x.Origin");
        //GMac.Bind("angle.1", "<x.Angle>");
        //GMac.Bind("x", "Point3D", "x.Point");
        //GMac.Bind("y", "Point3D", "p");
        double tmp0 = x.Axis.z * x.Axis.z + x.Axis.y * x.Axis.y + x.Axis.x * x.Axis.x;
        double tmp1 = 1.0 / tmp0;
        double tmp2 = Math.Sqrt(tmp1);
        var (tmp4, tmp3) = Math.SinCos(x.Angle);
        double tmp5 = 1.0 - tmp3;
        double tmp6 = x.Point.y - x.Origin.y;
        double tmp7 = x.Point.x - x.Origin.x;
        double tmp8 = x.Point.z - x.Origin.z;
        double tmp9 = tmp2 * tmp6;
        double tmp10 = tmp2 * tmp8;
        double tmp11 = (tmp8 * x.Axis.z + x.Axis.x * tmp7 + x.Axis.y * tmp6) * tmp1;
        double tmp13 = tmp4 * (x.Axis.y * tmp10 - x.Axis.z * tmp9) + x.Point.x - tmp5 * (tmp7 - x.Axis.x * tmp11);
        double tmp12 = tmp2 * tmp7;
        double tmp14 = tmp4 * (x.Axis.z * tmp12 - x.Axis.x * tmp10) + x.Point.y - tmp5 * (tmp6 - x.Axis.y * tmp11);
        p.z = tmp4 * (x.Axis.x * tmp9 - x.Axis.y * tmp12) + x.Point.z - tmp5 * (tmp8 - x.Axis.z * tmp11);
        p.x = tmp13;
        p.y = tmp14;
        #endregion
    }

    public static Vec3 Direct(in AxisRotationInput x)
    {
        var rotation = GeneralRotation(ConformalVector(x.Origin), ConformalVector(x.Axis), x.Angle);
        return ToVec3(rotation.Apply(Point(x.Point)));
    }

    /// <summary>(3.94) and (3.96): V_p V_R V_p⁻¹ with V_R = cos(φ/2) − sin(φ/2) R, R the unit plane a⌋I3, V_p = 1 − ½ p ni.</summary>
    private static Multivector<double> GeneralRotation(Multivector<double> p, Multivector<double> axis, double angle)
    {
        var plane = axis.Lcp(CgaI3);
        var rotation = Math.Cos(angle / 2) * CgaOne - Math.Sin(angle / 2) * (plane / plane.Norm());
        var vp = CgaOne - 0.5 * p.Op(CgaNi);
        return vp.Gp(rotation).Gp(vp.Inverse());
    }

    /// <summary>Rodrigues' rotation of x − o about the unit axis k, moved back by o.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Hand(in AxisRotationInput x, out Vec3 p)
    {
        ref readonly var a = ref x.Axis;
        ref readonly var o = ref x.Origin;
        var inverseLength = 1 / Math.Sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
        double kx = a.x * inverseLength, ky = a.y * inverseLength, kz = a.z * inverseLength;
        double c = Math.Cos(x.Angle), s = Math.Sin(x.Angle);
        double ux = x.Point.x - o.x, uy = x.Point.y - o.y, uz = x.Point.z - o.z;
        double cx = ky * uz - kz * uy, cy = kz * ux - kx * uz, cz = kx * uy - ky * ux;
        var f = (kx * ux + ky * uy + kz * uz) * (1 - c);
        p.x = o.x + ux * c + cx * s + kx * f;
        p.y = o.y + uy * c + cy * s + ky * f;
        p.z = o.z + uz * c + cz * s + kz * f;
    }
}
