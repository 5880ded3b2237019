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
        double tmp0 = p.z - origin.z;
        double tmp1 = origin.y - p.y;
        double tmp2 = tmp1 * axis.z + tmp0 * axis.y;
        double tmp3 = origin.x - p.x;
        double tmp4 = -(tmp3 * axis.z) - tmp0 * axis.x;
        double tmp5 = tmp3 * axis.y - tmp1 * axis.x;
        double tmp6 = 1.0 - Math.Cos(angle);
        double tmp7 = Math.Sin(angle);
        y.x = (tmp5 * axis.y - tmp4 * axis.z) * tmp6 + tmp2 * tmp7 + p.x;
        y.y = (tmp2 * axis.z - tmp5 * axis.x) * tmp6 + tmp4 * tmp7 + p.y;
        y.z = (tmp4 * axis.x - tmp2 * axis.y) * tmp6 + tmp5 * tmp7 + p.z;
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
        double tmp0 = p.y - origin.y;
        double tmp1 = p.z - origin.z;
        y.x = p.x;
        double tmp2 = Math.Sin(angle);
        double tmp3 = Math.Cos(angle);
        y.y = tmp0 * tmp3 + origin.y - tmp1 * tmp2;
        y.z = tmp0 * tmp2 + tmp1 * tmp3 + origin.z;
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
        double tmp0 = p.x - origin.x;
        double tmp1 = p.z - origin.z;
        double tmp2 = Math.Sin(angle);
        double tmp3 = Math.Cos(angle);
        y.x = tmp0 * tmp3 + tmp1 * tmp2 + origin.x;
        y.y = p.y;
        y.z = tmp1 * tmp3 + origin.z - tmp0 * tmp2;
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
        double tmp0 = p.x - origin.x;
        double tmp1 = p.y - origin.y;
        double tmp2 = Math.Sin(angle);
        double tmp3 = Math.Cos(angle);
        y.x = tmp0 * tmp3 + origin.x - tmp1 * tmp2;
        y.y = tmp0 * tmp2 + tmp1 * tmp3 + origin.y;
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
        double tmp0 = Math.Cos(angle);
        double tmp1 = Math.Sin(angle);
        double tmp2 = tmp0 - 1.0;
        double tmp3 = origin.y - x.y;
        double tmp4 = origin.z - x.z;
        double tmp5 = x.x - origin.x;
        double tmp6 = -(tmp2 * tmp5);
        double tmp7 = tmp3 * tmp1;
        double tmp8 = origin.z * tmp2;
        double tmp9 = tmp4 * tmp1;
        double tmp10 = origin.y * tmp2;
        y.x = axis.y * (axis.x * (tmp10 - x.y * tmp2) - axis.y * tmp6 - tmp9) + axis.z * (axis.x * (tmp8 - x.z * tmp2) + tmp7 - axis.z * tmp6) + x.x;
        double tmp11 = tmp3 * axis.y + tmp4 * axis.z;
        double tmp12 = tmp11 - tmp5 * axis.x;
        double tmp13 = tmp12 - tmp0 * tmp12;
        double tmp14 = -(axis.x * tmp4) - tmp5 * axis.z;
        y.y = x.y * tmp0 - axis.y * tmp13 - tmp1 * tmp14 - tmp10;
        double tmp15 = -(tmp3 * axis.x) - tmp5 * axis.y;
        y.z = tmp1 * tmp15 + x.z * tmp0 - axis.z * tmp13 - tmp8;
        double tmp16 = -(((-(axis.y * axis.y) - axis.z * axis.z) * tmp5 - tmp11 * axis.x) * tmp1) - (tmp3 * axis.z - axis.y * tmp4) * tmp0;
        double tmp17 = axis.x * tmp2;
        double tmp18 = xu.x * axis.z;
        double tmp19 = xu.x * axis.y;
        yu.x = axis.y * (tmp2 * tmp19 + xu.z * tmp1 - xu.y * tmp17) + axis.z * (tmp2 * tmp18 - xu.z * tmp17 - xu.y * tmp1) + xu.x - ru * tmp16;
        double tmp20 = tmp1 * tmp12;
        double tmp21 = xu.y * axis.y + xu.z * axis.z + xu.x * axis.x;
        double tmp22 = tmp21 - tmp21 * tmp0 - ru * tmp20;
        double tmp23 = tmp14 * tmp0 - tmp7;
        yu.y = axis.y * tmp22 + tmp1 * (tmp18 - axis.x * xu.z) + xu.y * tmp0 - ru * tmp23;
        double tmp24 = -(tmp15 * tmp0) - tmp9;
        yu.z = axis.z * tmp22 + tmp1 * (axis.x * xu.y - tmp19) + xu.z * tmp0 - ru * tmp24;
        double tmp25 = xv.x * axis.y;
        double tmp26 = xv.x * axis.z;
        yv.x = axis.y * (tmp2 * tmp25 + xv.z * tmp1 - xv.y * tmp17) + axis.z * (tmp2 * tmp26 - xv.z * tmp17 - xv.y * tmp1) + xv.x - rv * tmp16;
        double tmp27 = xv.x * axis.x + xv.y * axis.y + xv.z * axis.z;
        double tmp28 = tmp27 - tmp27 * tmp0 - rv * tmp20;
        yv.y = axis.y * tmp28 + tmp1 * (tmp26 - axis.x * xv.z) + xv.y * tmp0 - rv * tmp23;
        yv.z = axis.z * tmp28 + tmp1 * (axis.x * xv.y - tmp25) + xv.z * tmp0 - rv * tmp24;
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
        double tmp0 = Math.Cos(angle);
        double tmp1 = Math.Sin(angle);
        double tmp2 = tmp0 - 1.0;
        double tmp3 = x.y - origin.y;
        double tmp4 = origin.z - x.z;
        double tmp5 = origin.x - x.x;
        double tmp6 = tmp2 * tmp5;
        double tmp7 = tmp3 * tmp1;
        double tmp8 = origin.z * tmp2;
        double tmp9 = tmp4 * tmp1;
        double tmp10 = origin.y * tmp2;
        y.x = axis.y * (axis.x * (tmp10 - x.y * tmp2) - axis.y * tmp6 - tmp9) + axis.z * (axis.x * (tmp8 - x.z * tmp2) - axis.z * tmp6 - tmp7) + x.x;
        double tmp11 = axis.y * tmp3 - axis.z * tmp4;
        double tmp12 = axis.x * tmp5 - tmp11;
        double tmp13 = tmp12 - tmp0 * tmp12;
        double tmp14 = axis.x * tmp4 - axis.z * tmp5;
        y.y = tmp1 * tmp14 + x.y * tmp0 - axis.y * tmp13 - tmp10;
        double tmp15 = -(axis.x * tmp3) - axis.y * tmp5;
        y.z = x.z * tmp0 - axis.z * tmp13 - tmp1 * tmp15 - tmp8;
        double tmp16 = xu.x * axis.z - xu.z * axis.x;
        double tmp17 = xu.x * axis.y - xu.y * axis.x;
        yu.x = ru * (tmp1 * (axis.x * tmp11 - tmp5 * (-(axis.y * axis.y) - axis.z * axis.z)) + tmp0 * (-(tmp3 * axis.z) - tmp4 * axis.y)) + axis.y * (tmp2 * tmp17 + xu.z * tmp1) + axis.z * (tmp2 * tmp16 - xu.y * tmp1) + xu.x;
        double tmp18 = xu.x * axis.x + xu.y * axis.y + xu.z * axis.z;
        double tmp19 = ru * tmp1 * tmp12 + tmp18 * tmp0 - tmp18;
        yu.y = ru * (tmp0 * tmp14 - tmp7) + tmp1 * tmp16 + xu.y * tmp0 - axis.y * tmp19;
        yu.z = ru * (tmp9 - tmp0 * tmp15) + xu.z * tmp0 - axis.z * tmp19 - tmp1 * tmp17;
        #endregion

        p = y;
        du = yu;
    }

    /// <summary>A reflection turns the sense of rotation about the reflected axis around.</summary>
    protected internal override Twist TransformedBy(Twist by, double u, double v) =>
        new RotationTwist(by.Apply(Axis, u, v), by.Apply(Origin, u, v), by.PreservesOrientation ? Coefficient : -Coefficient, Map);
}
