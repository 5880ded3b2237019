using System.Runtime.CompilerServices;

namespace Twister;

/// <summary>(6.13) rotation by φ = c_r f_r(u, v) about the line through <see cref="Origin"/> along <see cref="Axis"/>.</summary>
public sealed class RotationTwist : Twist
{
    private readonly TwistableVector _unit;
    private readonly ScaledMap _angle;
    private readonly CoordinateAxis _along;
    private readonly double _sense;

    public RotationTwist(TwistableVector axis, TwistablePoint origin, double coefficient, ParameterMap map)
    {
        _unit = Require.UnitDirection(axis, nameof(axis));
        Require.Finite(origin, nameof(origin));
        Require.Finite(coefficient, nameof(coefficient));
        Require.NotNull(map, nameof(map));
        Axis = axis;
        Origin = origin;
        Coefficient = coefficient;
        Map = map;
        (_along, _sense) = CoordinateAxisOf(_unit);
        _angle = new(coefficient, map);
    }

    public static RotationTwist AboutX(double coefficient, ParameterMap map) => new(new(1, 0, 0), default, coefficient, map);
    public static RotationTwist AboutY(double coefficient, ParameterMap map) => new(new(0, 1, 0), default, coefficient, map);
    public static RotationTwist AboutZ(double coefficient, ParameterMap map) => new(new(0, 0, 1), default, coefficient, map);

    public TwistableVector Axis { get; }
    public TwistablePoint Origin { get; }
    public double Coefficient { get; }
    public ParameterMap Map { get; }

    public override bool IgnoresV => Map.IgnoresV;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public override TwistablePoint Apply(TwistablePoint p, double u, double v)
    {
        var angle = _angle.At(u, v);
        return _along switch
        {
            CoordinateAxis.X => AboutXPoint(p, _sense * angle),
            CoordinateAxis.Y => AboutYPoint(p, _sense * angle),
            CoordinateAxis.Z => AboutZPoint(p, _sense * angle),
            _ => GeneralPoint(p, angle),
        };
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private TwistablePoint GeneralPoint(TwistablePoint p, double angle)
    {
        var axis = _unit;
        var origin = Origin;
        var y = new TwistablePoint();

        #region GMac : RotationTwistPoint
        //GMac.Bind("axis", "Vector3D", axis);
        //GMac.Bind("origin", "Vector3D", origin);
        //GMac.Bind("angle.1", angle);
        //GMac.Bind("x", "Vector3D", p);
        //GMac.Bind("y", "Vector3D", y);
        var (tmp1, tmp0) = Math.SinCos(angle);
        double tmp2 = origin.z - p.z;
        double tmp3 = origin.y - p.y;
        double tmp4 = tmp3 * axis.z - tmp2 * axis.y;
        double tmp5 = origin.x - p.x;
        double tmp6 = tmp2 * axis.x - tmp5 * axis.z;
        double tmp7 = tmp5 * axis.y - tmp3 * axis.x;
        double tmp8 = 1.0 - tmp0;
        y.x = tmp4 * tmp1 + p.x - tmp8 * (tmp6 * axis.z - tmp7 * axis.y);
        y.y = tmp6 * tmp1 + p.y - tmp8 * (tmp7 * axis.x - tmp4 * axis.z);
        y.z = tmp7 * tmp1 + p.z - tmp8 * (tmp4 * axis.y - tmp6 * axis.x);
        #endregion

        return y;
    }

    // Fast paths: an axis along a coordinate axis (either sense; the sense is folded into the angle)
    // binds the literal unit axis, so the generated kernel is the plane rotation it reduces to.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private TwistablePoint AboutXPoint(TwistablePoint p, double angle)
    {
        var origin = Origin;
        var y = new TwistablePoint();

        #region GMac : RotationTwistPoint
        //GMac.Bind("axis.e1", 1);
        //GMac.Bind("origin", "Vector3D", origin);
        //GMac.Bind("angle.1", angle);
        //GMac.Bind("x", "Vector3D", p);
        //GMac.Bind("y", "Vector3D", y);
        //GMac.Bind("axis.e2", "0");
        //GMac.Bind("axis.e3", "0");
        var (tmp0, tmp1) = Math.SinCos(angle);
        y.x = p.x;
        double tmp2 = p.z - origin.z;
        double tmp3 = p.y - origin.y;
        y.y = tmp1 * tmp3 + origin.y - tmp0 * tmp2;
        y.z = tmp1 * tmp2 + tmp0 * tmp3 + origin.z;
        #endregion

        return y;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private TwistablePoint AboutYPoint(TwistablePoint p, double angle)
    {
        var origin = Origin;
        var y = new TwistablePoint();

        #region GMac : RotationTwistPoint
        //GMac.Bind("axis.e2", 1);
        //GMac.Bind("origin", "Vector3D", origin);
        //GMac.Bind("angle.1", angle);
        //GMac.Bind("x", "Vector3D", p);
        //GMac.Bind("y", "Vector3D", y);
        //GMac.Bind("axis.e1", "0");
        //GMac.Bind("axis.e3", "0");
        var (tmp0, tmp1) = Math.SinCos(angle);
        double tmp2 = p.z - origin.z;
        double tmp3 = p.x - origin.x;
        y.x = tmp1 * tmp3 + tmp0 * tmp2 + origin.x;
        y.y = p.y;
        y.z = tmp1 * tmp2 + origin.z - tmp0 * tmp3;
        #endregion

        return y;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private TwistablePoint AboutZPoint(TwistablePoint p, double angle)
    {
        var origin = Origin;
        var y = new TwistablePoint();

        #region GMac : RotationTwistPoint
        //GMac.Bind("axis.e3", 1);
        //GMac.Bind("origin", "Vector3D", origin);
        //GMac.Bind("angle.1", angle);
        //GMac.Bind("x", "Vector3D", p);
        //GMac.Bind("y", "Vector3D", y);
        //GMac.Bind("axis.e1", "0");
        //GMac.Bind("axis.e2", "0");
        var (tmp0, tmp1) = Math.SinCos(angle);
        double tmp2 = p.y - origin.y;
        double tmp3 = p.x - origin.x;
        y.x = tmp1 * tmp3 + origin.x - tmp0 * tmp2;
        y.y = tmp1 * tmp2 + tmp0 * tmp3 + origin.y;
        y.z = p.z;
        #endregion

        return y;
    }

    /// <summary>The coordinate axis <paramref name="unit"/> lies along, if any, and its sense (±1).</summary>
    private static (CoordinateAxis Along, double Sense) CoordinateAxisOf(TwistableVector unit) => unit switch
    {
        { y: 0, z: 0 } => (CoordinateAxis.X, Math.Sign(unit.x)),
        { x: 0, z: 0 } => (CoordinateAxis.Y, Math.Sign(unit.y)),
        { x: 0, y: 0 } => (CoordinateAxis.Z, Math.Sign(unit.z)),
        _ => (CoordinateAxis.None, 1.0),
    };

    private enum CoordinateAxis { None, X, Y, Z }

    public override TwistableVector Apply(TwistableVector d, double u, double v) => RotationKernels.Rotate(_unit, _angle.At(u, v), d);

    public override TwistableBivector Apply(TwistableBivector b, double u, double v) => RotationKernels.Rotate(_unit, _angle.At(u, v), b);

    public override void ApplyWithTangents(ref TwistablePoint p, ref TwistableVector du, ref TwistableVector dv, double u, double v)
    {
        var axis = _unit;
        var origin = Origin;
        var angle = _angle.At(u, v);
        var ru = _angle.DerivativeU(u, v);
        var rv = _angle.DerivativeV(u, v);
        TwistablePoint x = p, y = new();
        TwistableVector xu = du, xv = dv, yu = new(), yv = new();

        #region GMac : RotationTwistPointTangents
        //GMac.Bind("axis", "Vector3D", axis);
        //GMac.Bind("origin", "Vector3D", origin);
        //GMac.Bind("angle.1", angle);
        //GMac.Bind("ru.1", ru);
        //GMac.Bind("rv.1", rv);
        //GMac.Bind("x", "Vector3D", x);
        //GMac.Bind("du", "Vector3D", xu);
        //GMac.Bind("dv", "Vector3D", xv);
        //GMac.Bind("y", "Vector3D", y);
        //GMac.Bind("yu", "Vector3D", yu);
        //GMac.Bind("yv", "Vector3D", yv);
        var (tmp1, tmp0) = Math.SinCos(angle);
        double tmp2 = axis.z * axis.z + axis.y * axis.y;
        double tmp3 = origin.z - x.z;
        double tmp4 = origin.y - x.y;
        double tmp5 = origin.x - x.x;
        double tmp6 = tmp0 - 1.0;
        double tmp7 = tmp3 * axis.y - tmp4 * axis.z;
        double tmp8 = tmp3 * axis.z + tmp4 * axis.y;
        double tmp9 = tmp5 * tmp2 - tmp8 * axis.x;
        y.x = x.x - tmp1 * tmp7 - tmp6 * tmp9;
        double tmp10 = tmp8 + tmp5 * axis.x;
        double tmp11 = axis.y * tmp10 - tmp4;
        double tmp12 = tmp3 * axis.x - tmp5 * axis.z;
        y.y = tmp1 * tmp12 + x.y + tmp6 * tmp11;
        double tmp13 = tmp3 - axis.z * tmp10;
        double tmp14 = tmp4 * axis.x - tmp5 * axis.y;
        y.z = x.z - tmp6 * tmp13 - tmp1 * tmp14;
        double tmp15 = tmp7 * tmp0 - tmp9 * tmp1;
        double tmp16 = tmp2 - tmp2 * tmp0 - 1.0;
        double tmp17 = tmp6 * axis.x;
        double tmp18 = xu.y * axis.y + xu.z * axis.z;
        yu.x = tmp1 * (axis.y * xu.z - xu.y * axis.z) - ru * tmp15 - xu.x * tmp16 - tmp18 * tmp17;
        double tmp19 = xu.x * axis.x + tmp18;
        double tmp20 = tmp19 * tmp0 - tmp19;
        double tmp21 = tmp11 * tmp1 - tmp0 * tmp12;
        yu.y = tmp1 * (xu.x * axis.z - axis.x * xu.z) + xu.y * tmp0 - ru * tmp21 - axis.y * tmp20;
        double tmp22 = tmp13 * tmp1 - tmp14 * tmp0;
        yu.z = ru * tmp22 + tmp1 * (axis.x * xu.y - axis.y * xu.x) + xu.z * tmp0 - axis.z * tmp20;
        double tmp23 = xv.z * axis.z + xv.y * axis.y;
        yv.x = tmp1 * (axis.y * xv.z - xv.y * axis.z) - rv * tmp15 - xv.x * tmp16 - tmp23 * tmp17;
        double tmp24 = xv.x * axis.x + tmp23;
        double tmp25 = tmp24 * tmp0 - tmp24;
        yv.y = tmp1 * (xv.x * axis.z - axis.x * xv.z) + xv.y * tmp0 - rv * tmp21 - axis.y * tmp25;
        yv.z = rv * tmp22 + tmp1 * (axis.x * xv.y - axis.y * xv.x) + xv.z * tmp0 - axis.z * tmp25;
        #endregion

        p = y;
        du = yu;
        dv = yv;
    }

    public override void ApplyWithTangent(ref TwistablePoint p, ref TwistableVector du, double u, double v)
    {
        var axis = _unit;
        var origin = Origin;
        var angle = _angle.At(u, v);
        var ru = _angle.DerivativeU(u, v);
        TwistablePoint x = p, y = new();
        TwistableVector xu = du, yu = new();

        #region GMac : RotationTwistPointTangents
        //GMac.Bind("axis", "Vector3D", axis);
        //GMac.Bind("origin", "Vector3D", origin);
        //GMac.Bind("angle.1", angle);
        //GMac.Bind("ru.1", ru);
        //GMac.Bind("x", "Vector3D", x);
        //GMac.Bind("du", "Vector3D", xu);
        //GMac.Bind("y", "Vector3D", y);
        //GMac.Bind("yu", "Vector3D", yu);
        //GMac.Bind("rv.1", "0");
        //GMac.Bind("dv.e1", "0");
        //GMac.Bind("dv.e2", "0");
        //GMac.Bind("dv.e3", "0");
        var (tmp1, tmp0) = Math.SinCos(angle);
        double tmp2 = axis.y * axis.y + axis.z * axis.z;
        double tmp3 = x.z - origin.z;
        double tmp4 = origin.y - x.y;
        double tmp5 = origin.x - x.x;
        double tmp6 = tmp0 - 1.0;
        double tmp7 = axis.y * tmp3 + axis.z * tmp4;
        double tmp8 = axis.z * tmp3 - axis.y * tmp4;
        double tmp9 = tmp2 * tmp5 + tmp8 * axis.x;
        y.x = tmp1 * tmp7 + x.x - tmp6 * tmp9;
        double tmp10 = tmp8 - axis.x * tmp5;
        double tmp11 = axis.z * tmp5 + axis.x * tmp3;
        double tmp12 = axis.y * tmp10 + tmp4;
        y.y = x.y - tmp1 * tmp11 - tmp6 * tmp12;
        double tmp13 = axis.x * tmp4 - axis.y * tmp5;
        double tmp14 = axis.z * tmp10 - tmp3;
        y.z = x.z - tmp1 * tmp13 - tmp6 * tmp14;
        double tmp15 = xu.y * axis.y + xu.z * axis.z;
        yu.x = ru * (tmp1 * tmp9 + tmp0 * tmp7) + xu.x * (tmp0 * tmp2 + 1.0 - tmp2) + tmp1 * (axis.y * xu.z - xu.y * axis.z) - axis.x * tmp6 * tmp15;
        double tmp16 = tmp15 + xu.x * axis.x;
        double tmp17 = tmp16 - tmp16 * tmp0;
        yu.y = ru * (tmp1 * tmp12 - tmp0 * tmp11) + axis.y * tmp17 + tmp1 * (xu.x * axis.z - axis.x * xu.z) + xu.y * tmp0;
        yu.z = ru * (tmp1 * tmp14 - tmp0 * tmp13) + axis.z * tmp17 + tmp1 * (axis.x * xu.y - axis.y * xu.x) + xu.z * tmp0;
        #endregion

        p = y;
        du = yu;
    }

    /// <summary>A reflection turns the sense of rotation about the reflected axis around.</summary>
    protected internal override Twist TransformedBy(Twist by, double u, double v) =>
        new RotationTwist(by.Apply(Axis, u, v), by.Apply(Origin, u, v), by.PreservesOrientation ? Coefficient : -Coefficient, Map);
}
