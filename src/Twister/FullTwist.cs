using System.Runtime.CompilerServices;

namespace Twister;

/// <summary>
/// A full twist (thesis Figure 6-6): rotation by φ = c_r f_r(u, v) about the line through
/// <see cref="Origin"/> along <see cref="Axis"/>, then a slide by c_t f_t(u, v) · <see cref="Axis"/>
/// along the same line (the axis as given, as in (6.12)).
/// </summary>
public sealed class FullTwist : Twist
{
    private readonly TwistableVector _unit;
    private readonly ScaledMap _angle, _slide;

    public FullTwist(TwistableVector axis, TwistablePoint origin, double angleCoefficient, ParameterMap angleMap,
        double slideCoefficient, ParameterMap slideMap)
    {
        _unit = Require.UnitDirection(axis, nameof(axis));
        Require.Finite(origin, nameof(origin));
        Require.Finite(angleCoefficient, nameof(angleCoefficient));
        Require.Finite(slideCoefficient, nameof(slideCoefficient));
        Require.NotNull(angleMap, nameof(angleMap));
        Require.NotNull(slideMap, nameof(slideMap));
        Axis = axis;
        Origin = origin;
        AngleCoefficient = angleCoefficient;
        AngleMap = angleMap;
        SlideCoefficient = slideCoefficient;
        SlideMap = slideMap;
        _angle = new(angleCoefficient, angleMap);
        _slide = new(slideCoefficient, slideMap);
    }

    /// <summary>A constant twist by <paramref name="angle"/> and <paramref name="slide"/> (the parameters of Figure 6-6).</summary>
    public FullTwist(TwistableVector axis, TwistablePoint origin, double angle, double slide)
        : this(axis, origin, angle, ParameterMap.One, slide, ParameterMap.One)
    {
    }

    public TwistableVector Axis { get; }
    public TwistablePoint Origin { get; }
    public double AngleCoefficient { get; }
    public ParameterMap AngleMap { get; }
    public double SlideCoefficient { get; }
    public ParameterMap SlideMap { get; }

    public override bool IgnoresV => AngleMap.IgnoresV && SlideMap.IgnoresV;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public override TwistablePoint Apply(TwistablePoint p, double u, double v)
    {
        var axis = Axis;
        var unit = _unit;
        var origin = Origin;
        var angle = _angle.At(u, v);
        var slide = _slide.At(u, v);
        var y = new TwistablePoint();

        #region GMac : FullTwistPoint
        //GMac.Bind("axis", "Vector3D", axis);
        //GMac.Bind("unit", "Vector3D", unit);
        //GMac.Bind("origin", "Vector3D", origin);
        //GMac.Bind("angle.1", angle);
        //GMac.Bind("slide.1", slide);
        //GMac.Bind("x", "Vector3D", p);
        //GMac.Bind("y", "Vector3D", y);
        var (tmp1, tmp0) = Math.SinCos(angle);
        double tmp2 = origin.z - p.z;
        double tmp3 = origin.y - p.y;
        double tmp4 = tmp3 * unit.z - tmp2 * unit.y;
        double tmp5 = origin.x - p.x;
        double tmp6 = tmp2 * unit.x - tmp5 * unit.z;
        double tmp7 = tmp5 * unit.y - tmp3 * unit.x;
        double tmp8 = tmp0 - 1.0;
        y.x = tmp4 * tmp1 + axis.x * slide + p.x + tmp8 * (tmp6 * unit.z - tmp7 * unit.y);
        y.y = tmp6 * tmp1 + axis.y * slide + p.y + tmp8 * (tmp7 * unit.x - tmp4 * unit.z);
        y.z = tmp7 * tmp1 + slide * axis.z + p.z + tmp8 * (tmp4 * unit.y - tmp6 * unit.x);
        #endregion

        return y;
    }

    public override TwistableVector Apply(TwistableVector d, double u, double v) => RotationKernels.Rotate(_unit, _angle.At(u, v), d);

    public override TwistableBivector Apply(TwistableBivector b, double u, double v) => RotationKernels.Rotate(_unit, _angle.At(u, v), b);

    public override void ApplyWithTangents(ref TwistablePoint p, ref TwistableVector du, ref TwistableVector dv, double u, double v)
    {
        var axis = Axis;
        var unit = _unit;
        var origin = Origin;
        var angle = _angle.At(u, v);
        var slide = _slide.At(u, v);
        var angleRu = _angle.DerivativeU(u, v);
        var angleRv = _angle.DerivativeV(u, v);
        var slideRu = _slide.DerivativeU(u, v);
        var slideRv = _slide.DerivativeV(u, v);
        TwistablePoint x = p, y = new();
        TwistableVector xu = du, xv = dv, yu = new(), yv = new();

        #region GMac : FullTwistPointTangents
        //GMac.Bind("axis", "Vector3D", axis);
        //GMac.Bind("unit", "Vector3D", unit);
        //GMac.Bind("origin", "Vector3D", origin);
        //GMac.Bind("angle.1", angle);
        //GMac.Bind("slide.1", slide);
        //GMac.Bind("angleRu.1", angleRu);
        //GMac.Bind("angleRv.1", angleRv);
        //GMac.Bind("slideRu.1", slideRu);
        //GMac.Bind("slideRv.1", slideRv);
        //GMac.Bind("x", "Vector3D", x);
        //GMac.Bind("du", "Vector3D", xu);
        //GMac.Bind("dv", "Vector3D", xv);
        //GMac.Bind("y", "Vector3D", y);
        //GMac.Bind("yu", "Vector3D", yu);
        //GMac.Bind("yv", "Vector3D", yv);
        var (tmp1, tmp0) = Math.SinCos(angle);
        double tmp2 = unit.y * unit.y + unit.z * unit.z;
        double tmp3 = origin.z - x.z;
        double tmp4 = origin.y - x.y;
        double tmp5 = origin.x - x.x;
        double tmp6 = tmp0 - 1.0;
        double tmp7 = tmp4 * unit.z - tmp3 * unit.y;
        double tmp8 = tmp3 * unit.z + tmp4 * unit.y;
        double tmp9 = tmp5 * tmp2 - tmp8 * unit.x;
        y.x = tmp1 * tmp7 + axis.x * slide + x.x - tmp6 * tmp9;
        double tmp10 = tmp8 + tmp5 * unit.x;
        double tmp11 = tmp5 * unit.z - tmp3 * unit.x;
        double tmp12 = tmp4 - unit.y * tmp10;
        y.y = axis.y * slide + x.y - tmp6 * tmp12 - tmp1 * tmp11;
        double tmp13 = tmp3 - unit.z * tmp10;
        double tmp14 = tmp4 * unit.x - tmp5 * unit.y;
        y.z = slide * axis.z + x.z - tmp1 * tmp14 - tmp6 * tmp13;
        double tmp15 = tmp7 * tmp0 + tmp9 * tmp1;
        double tmp16 = tmp2 - tmp2 * tmp0 - 1.0;
        double tmp17 = xu.y * unit.y + xu.z * unit.z;
        double tmp18 = tmp6 * unit.x;
        yu.x = angleRu * tmp15 + tmp1 * (xu.z * unit.y - xu.y * unit.z) + axis.x * slideRu - xu.x * tmp16 - tmp17 * tmp18;
        double tmp19 = tmp17 + xu.x * unit.x;
        double tmp20 = tmp19 * tmp0 - tmp19;
        double tmp21 = tmp12 * tmp1 - tmp11 * tmp0;
        yu.y = angleRu * tmp21 + tmp1 * (xu.x * unit.z - xu.z * unit.x) + axis.y * slideRu + xu.y * tmp0 - unit.y * tmp20;
        double tmp22 = tmp0 * tmp14 - tmp13 * tmp1;
        yu.z = tmp1 * (xu.y * unit.x - xu.x * unit.y) + slideRu * axis.z + xu.z * tmp0 - angleRu * tmp22 - unit.z * tmp20;
        double tmp23 = unit.z * xv.z + xv.y * unit.y;
        yv.x = angleRv * tmp15 + tmp1 * (xv.z * unit.y - xv.y * unit.z) + axis.x * slideRv - xv.x * tmp16 - tmp23 * tmp18;
        double tmp24 = xv.x * unit.x + tmp23;
        double tmp25 = tmp24 * tmp0 - tmp24;
        yv.y = angleRv * tmp21 + tmp1 * (xv.x * unit.z - xv.z * unit.x) + axis.y * slideRv + xv.y * tmp0 - unit.y * tmp25;
        yv.z = tmp1 * (xv.y * unit.x - xv.x * unit.y) + slideRv * axis.z + xv.z * tmp0 - angleRv * tmp22 - unit.z * tmp25;
        #endregion

        p = y;
        du = yu;
        dv = yv;
    }

    public override void ApplyWithTangent(ref TwistablePoint p, ref TwistableVector du, double u, double v)
    {
        var axis = Axis;
        var unit = _unit;
        var origin = Origin;
        var angle = _angle.At(u, v);
        var slide = _slide.At(u, v);
        var angleRu = _angle.DerivativeU(u, v);
        var slideRu = _slide.DerivativeU(u, v);
        TwistablePoint x = p, y = new();
        TwistableVector xu = du, yu = new();

        #region GMac : FullTwistPointTangents
        //GMac.Bind("axis", "Vector3D", axis);
        //GMac.Bind("unit", "Vector3D", unit);
        //GMac.Bind("origin", "Vector3D", origin);
        //GMac.Bind("angle.1", angle);
        //GMac.Bind("slide.1", slide);
        //GMac.Bind("angleRu.1", angleRu);
        //GMac.Bind("slideRu.1", slideRu);
        //GMac.Bind("x", "Vector3D", x);
        //GMac.Bind("du", "Vector3D", xu);
        //GMac.Bind("y", "Vector3D", y);
        //GMac.Bind("yu", "Vector3D", yu);
        //GMac.Bind("angleRv.1", "0");
        //GMac.Bind("slideRv.1", "0");
        //GMac.Bind("dv.e1", "0");
        //GMac.Bind("dv.e2", "0");
        //GMac.Bind("dv.e3", "0");
        var (tmp1, tmp0) = Math.SinCos(angle);
        double tmp2 = unit.z * unit.z + unit.y * unit.y;
        double tmp3 = x.z - origin.z;
        double tmp4 = x.y - origin.y;
        double tmp5 = origin.x - x.x;
        double tmp6 = tmp0 - 1.0;
        double tmp7 = unit.z * tmp4 - unit.y * tmp3;
        double tmp8 = unit.y * tmp4 + unit.z * tmp3;
        double tmp9 = tmp8 * unit.x + tmp2 * tmp5;
        y.x = axis.x * slide + x.x - tmp1 * tmp7 - tmp6 * tmp9;
        double tmp10 = tmp5 * unit.x - tmp8;
        double tmp11 = unit.x * tmp3 + unit.z * tmp5;
        double tmp12 = unit.y * tmp10 + tmp4;
        y.y = axis.y * slide + x.y + tmp6 * tmp12 - tmp1 * tmp11;
        double tmp13 = unit.x * tmp4 + unit.y * tmp5;
        double tmp14 = unit.z * tmp10 + tmp3;
        y.z = tmp1 * tmp13 + slide * axis.z + x.z + tmp6 * tmp14;
        double tmp15 = xu.y * unit.y + xu.z * unit.z;
        yu.x = angleRu * (tmp1 * tmp9 - tmp0 * tmp7) + xu.x * (tmp0 * tmp2 + 1.0 - tmp2) + tmp1 * (xu.z * unit.y - xu.y * unit.z) + axis.x * slideRu - unit.x * tmp6 * tmp15;
        double tmp16 = xu.x * unit.x + tmp15;
        double tmp17 = tmp16 - tmp16 * tmp0;
        yu.y = xu.y * tmp0 - (angleRu * (tmp1 * tmp12 + tmp0 * tmp11) - unit.y * tmp17 - tmp1 * (xu.x * unit.z - xu.z * unit.x) - axis.y * slideRu);
        yu.z = angleRu * (tmp0 * tmp13 - tmp1 * tmp14) + unit.z * tmp17 + tmp1 * (xu.y * unit.x - xu.x * unit.y) + slideRu * axis.z + xu.z * tmp0;
        #endregion

        p = y;
        du = yu;
    }

    /// <summary>
    /// The axis moves as a direction, so the slide c_t f_t · axis moves with it; a reflection turns
    /// the sense of rotation around.
    /// </summary>
    protected internal override Twist TransformedBy(Twist by, double u, double v) =>
        new FullTwist(by.Apply(Axis, u, v), by.Apply(Origin, u, v), by.PreservesOrientation ? AngleCoefficient : -AngleCoefficient,
            AngleMap, SlideCoefficient, SlideMap);
}
