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
        double tmp0 = 0.5 * x.Slide;
        double tmp1 = -(x.Axis.x * tmp0);
        double tmp2 = -(x.Axis.y * tmp0);
        double tmp3 = -(x.Axis.z * tmp0);
        double tmp4 = 0.5 * x.Angle;
        double tmp5 = Math.Cos(tmp4);
        double tmp6 = Math.Sin(tmp4) / Math.Sqrt(x.Axis.x * x.Axis.x + x.Axis.y * x.Axis.y + x.Axis.z * x.Axis.z);
        double tmp7 = -(x.Axis.z * tmp6);
        double tmp8 = x.Axis.y * tmp6;
        double tmp9 = -(x.Axis.x * tmp6);
        double tmp10 = x.Origin.z - tmp3;
        double tmp11 = x.Origin.y - tmp2;
        double tmp12 = tmp7 * tmp11 + tmp8 * tmp10 + tmp1 * tmp5;
        double tmp13 = tmp1 - x.Origin.x;
        double tmp14 = tmp9 * tmp10 + tmp7 * tmp13 + tmp2 * tmp5;
        double tmp15 = tmp8 * tmp13 + tmp3 * tmp5 - tmp9 * tmp11;
        double tmp16 = tmp1 * tmp9 + tmp3 * tmp7 - tmp2 * tmp8;
        double tmp17 = x.Point.x * tmp5;
        double tmp18 = x.Point.z * tmp8;
        double tmp19 = x.Point.y * tmp7;
        double tmp20 = x.Point.x * tmp8;
        double tmp21 = 2.0 * tmp15;
        double tmp22 = x.Point.x * tmp7;
        double tmp23 = 2.0 * tmp14;
        double tmp24 = x.Point.y * tmp8;
        double tmp25 = x.Point.z * tmp7;
        double tmp26 = tmp12 - tmp19;
        p.x = tmp9 * (2.0 * (tmp25 - tmp16 - tmp24) + tmp9 * x.Point.x) + tmp5 * (2.0 * (tmp18 - tmp26) + tmp17) + tmp7 * (-tmp23 - tmp22) + tmp8 * (-tmp21 - tmp20);
        double tmp27 = 2.0 * tmp16;
        double tmp28 = x.Point.y * tmp5;
        double tmp29 = x.Point.z * tmp5;
        p.y = tmp9 * (2.0 * (tmp29 - tmp15 - tmp20) - tmp9 * x.Point.y) + tmp7 * (2.0 * (tmp12 - tmp17 - tmp18) - tmp19) + tmp5 * (tmp28 - tmp23) + tmp8 * (tmp27 + tmp24);
        p.z = tmp9 * (2.0 * (tmp14 + tmp22 - tmp28) - tmp9 * x.Point.z) + tmp8 * (2.0 * (tmp26 - tmp17) - tmp18) + tmp5 * (tmp29 - tmp21) + tmp7 * (tmp25 - tmp27);
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
