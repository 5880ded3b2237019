using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using GMac.Core.Algebra;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>Figure 6-6: a twist (rotation about an axis through a point, then a slide along the axis) applied to a point.</summary>
public sealed class ApplyTwistToPoint3DKernel : GaKernel<TwistInput, Vec3>
{
    public override string MacroName => "ApplyTwistToPoint3D";
    public override string Source => "thesis Figure 6-6, (3.93)-(3.97)";

    /// <summary>
    /// Counted by hand, Rodrigues' formula: |a|² (3 mul, 2 add), sqrt, 1/|a| (1 div), k = a/|a| (3 mul),
    /// cos, sin, u = x − o (3 add), k×u (6 mul, 3 add), k·u (3 mul, 2 add), (k·u)(1 − cos) (1 mul, 1 add),
    /// o + u cos + (k×u) sin + k f + d a (12 mul, 12 add).
    /// </summary>
    public override OperationCount HandOperations => new(Additions: 23, Multiplications: 28, Divisions: 1, Calls: 3);

    protected override TwistInput CreateInput(Random random) => new()
    {
        Axis = new(Signed(random) + 2, Signed(random), Signed(random)),
        Origin = new(Signed(random), Signed(random), Signed(random)),
        Angle = Signed(random) * Math.PI,
        Slide = Signed(random),
        Point = new(Signed(random), Signed(random), Signed(random)),
    };

    protected override double[] Components(Vec3 v) => [v.x, v.y, v.z];

    protected override void RunGenerated(TwistInput[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Generated(in inputs[i], out outputs[i]);
    }

    protected override void RunDirect(TwistInput[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Direct(in inputs[i]);
    }

    protected override void RunHand(TwistInput[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Hand(in inputs[i], out outputs[i]);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Generated(in TwistInput x, out Vec3 p)
    {
        #region GMac : ApplyTwistToPoint3D
        //GMac.Bind("rot_axis", "Vector3D", "x.Axis");
        //GMac.Bind("tr_origin", "Vector3D", "x.Origin");
        //GMac.Bind("angle.1", "<x.Angle>");
        //GMac.Bind("tr_param.1", "<x.Slide>");
        //GMac.Bind("in_mv", "Point3D", "x.Point");
        //GMac.Bind("out_mv", "Point3D", "p");
        double tmp0 = x.Axis.z * x.Axis.z + x.Axis.y * x.Axis.y + x.Axis.x * x.Axis.x;
        double tmp1 = 1.0 / tmp0;
        double tmp2 = Math.Sqrt(tmp1);
        var (tmp4, tmp3) = Math.SinCos(x.Angle);
        double tmp5 = tmp3 - 1.0;
        double tmp6 = x.Origin.x - x.Point.x;
        double tmp7 = x.Point.z - x.Origin.z;
        double tmp8 = x.Point.y - x.Origin.y;
        double tmp9 = tmp2 * tmp8;
        double tmp10 = tmp2 * tmp7;
        double tmp11 = (tmp8 * x.Axis.y + tmp7 * x.Axis.z - x.Axis.x * tmp6) * tmp1;
        double tmp13 = tmp4 * (x.Axis.y * tmp10 - x.Axis.z * tmp9) + x.Axis.x * x.Slide + x.Point.x - tmp5 * (x.Axis.x * tmp11 + tmp6);
        double tmp12 = tmp2 * tmp6;
        double tmp14 = tmp5 * (tmp8 - x.Axis.y * tmp11) - (tmp4 * (x.Axis.x * tmp10 + x.Axis.z * tmp12) - x.Axis.y * x.Slide - x.Point.y);
        p.z = tmp4 * (x.Axis.y * tmp12 + x.Axis.x * tmp9) + x.Point.z + x.Axis.z * x.Slide + tmp5 * (tmp7 - x.Axis.z * tmp11);
        p.x = tmp13;
        p.y = tmp14;
        #endregion
    }

    public static Vec3 Direct(in TwistInput x)
    {
        var axis = ConformalVector(x.Axis);
        var twist = Translation(x.Slide * axis).Gp(GeneralRotation(ConformalVector(x.Origin), axis, x.Angle));
        return ToVec3(twist.Apply(Point(x.Point)));
    }

    /// <summary>(3.93) V_t = 1 − ½ t ^ ni.</summary>
    private static Multivector<double> Translation(Multivector<double> t) => CgaOne - 0.5 * t.Op(CgaNi);

    /// <summary>(3.94) and (3.96): V_p V_R V_p⁻¹ with V_R = cos(φ/2) − sin(φ/2) R, R the unit plane a⌋I3.</summary>
    private static Multivector<double> GeneralRotation(Multivector<double> p, Multivector<double> axis, double angle)
    {
        var plane = axis.Lcp(CgaI3);
        var rotation = Math.Cos(angle / 2) * CgaOne - Math.Sin(angle / 2) * (plane / plane.Norm());
        var vp = Translation(p);
        return vp.Gp(rotation).Gp(vp.Inverse());
    }

    /// <summary>Rodrigues' rotation of x − o about the unit axis k, moved back by o and slid by d a.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Hand(in TwistInput x, out Vec3 p)
    {
        ref readonly var a = ref x.Axis;
        ref readonly var o = ref x.Origin;
        var inverseLength = 1 / Math.Sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
        double kx = a.x * inverseLength, ky = a.y * inverseLength, kz = a.z * inverseLength;
        double c = Math.Cos(x.Angle), s = Math.Sin(x.Angle);
        double ux = x.Point.x - o.x, uy = x.Point.y - o.y, uz = x.Point.z - o.z;
        double cx = ky * uz - kz * uy, cy = kz * ux - kx * uz, cz = kx * uy - ky * ux;
        var f = (kx * ux + ky * uy + kz * uz) * (1 - c);
        var d = x.Slide;
        p.x = o.x + ux * c + cx * s + kx * f + d * a.x;
        p.y = o.y + uy * c + cy * s + ky * f + d * a.y;
        p.z = o.z + uz * c + cz * s + kz * f + d * a.z;
    }
}
