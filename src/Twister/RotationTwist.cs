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
        double tmp0 = origin.y - p.y;
        double tmp1 = p.z - origin.z;
        double tmp2 = axis.y * tmp1 + axis.z * tmp0;
        double tmp3 = origin.x - p.x;
        double tmp4 = -(axis.x * tmp1) - axis.z * tmp3;
        double tmp5 = axis.y * tmp3 - axis.x * tmp0;
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
        double tmp6 = tmp2 * tmp5;
        double tmp7 = tmp3 * tmp1;
        double tmp8 = origin.z * tmp2;
        double tmp9 = tmp4 * tmp1;
        double tmp10 = origin.y * tmp2;
        y.x = axis.y * (axis.x * (tmp10 - x.y * tmp2) + axis.y * tmp6 - tmp9) + axis.z * (axis.x * (tmp8 - x.z * tmp2) + axis.z * tmp6 + tmp7) + x.x;
        double tmp11 = tmp4 * axis.z + tmp3 * axis.y;
        double tmp12 = tmp11 - tmp5 * axis.x;
        double tmp13 = tmp12 - tmp12 * tmp0;
        double tmp14 = tmp5 * axis.z;
        double tmp15 = tmp4 * axis.x + tmp14;
        y.y = tmp1 * tmp15 + x.y * tmp0 - axis.y * tmp13 - tmp10;
        double tmp16 = tmp5 * axis.y;
        double tmp17 = -(tmp3 * axis.x) - tmp16;
        y.z = tmp1 * tmp17 + x.z * tmp0 - axis.z * tmp13 - tmp8;
        double tmp18 = (tmp3 * axis.z - axis.y * tmp4) * tmp0 + (-(axis.y * tmp16) - axis.z * tmp14 - tmp11 * axis.x) * tmp1;
        double tmp19 = axis.x * tmp2;
        double tmp20 = xu.x * axis.y;
        double tmp21 = xu.x * axis.z;
        yu.x = ru * tmp18 + axis.y * (tmp2 * tmp20 + xu.z * tmp1 - xu.y * tmp19) + axis.z * (tmp2 * tmp21 - xu.z * tmp19 - xu.y * tmp1) + xu.x;
        double tmp22 = tmp1 * tmp12;
        double tmp23 = xu.y * axis.y + xu.z * axis.z + xu.x * axis.x;
        double tmp24 = tmp23 - tmp23 * tmp0 - ru * tmp22;
        double tmp25 = -tmp7 - tmp15 * tmp0;
        yu.y = axis.y * tmp24 + tmp1 * (tmp21 - axis.x * xu.z) + xu.y * tmp0 - ru * tmp25;
        double tmp26 = -(tmp17 * tmp0) - tmp9;
        yu.z = axis.z * tmp24 + tmp1 * (axis.x * xu.y - tmp20) + xu.z * tmp0 - ru * tmp26;
        double tmp27 = xv.x * tmp2;
        yv.x = rv * tmp18 + axis.y * (axis.y * tmp27 + xv.z * tmp1 - xv.y * tmp19) + axis.z * (axis.z * tmp27 - xv.z * tmp19 - xv.y * tmp1) + xv.x;
        double tmp28 = xv.x * axis.x + xv.y * axis.y + xv.z * axis.z;
        double tmp29 = tmp28 - tmp28 * tmp0 - rv * tmp22;
        yv.y = axis.y * tmp29 + tmp1 * (xv.x * axis.z - axis.x * xv.z) + xv.y * tmp0 - rv * tmp25;
        yv.z = axis.z * tmp29 + tmp1 * (axis.x * xv.y - axis.y * xv.x) + xv.z * tmp0 - rv * tmp26;
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
        double tmp13 = tmp12 * tmp0 - tmp12;
        double tmp14 = axis.z * tmp5;
        double tmp15 = tmp14 - axis.x * tmp4;
        y.y = axis.y * tmp13 + x.y * tmp0 - tmp1 * tmp15 - tmp10;
        double tmp16 = axis.y * tmp5;
        double tmp17 = -(axis.x * tmp3) - tmp16;
        y.z = axis.z * tmp13 + x.z * tmp0 - tmp1 * tmp17 - tmp8;
        double tmp18 = xu.x * tmp2;
        double tmp19 = xu.z * axis.x;
        double tmp20 = xu.y * axis.x;
        yu.x = ru * (tmp1 * (axis.x * tmp11 + axis.y * tmp16 + axis.z * tmp14) + tmp0 * (-(axis.y * tmp4) - axis.z * tmp3)) + axis.y * (axis.y * tmp18 + xu.z * tmp1 - tmp2 * tmp20) + axis.z * (axis.z * tmp18 - tmp2 * tmp19 - xu.y * tmp1) + xu.x;
        double tmp21 = xu.x * axis.x + xu.y * axis.y + xu.z * axis.z;
        double tmp22 = tmp21 - tmp12 * ru * tmp1 - tmp21 * tmp0;
        yu.y = axis.y * tmp22 + ru * (-(tmp0 * tmp15) - tmp7) + tmp1 * (xu.x * axis.z - tmp19) + xu.y * tmp0;
        yu.z = axis.z * tmp22 + ru * (tmp9 - tmp0 * tmp17) + tmp1 * (tmp20 - axis.y * xu.x) + xu.z * tmp0;
        #endregion

        p = y;
        du = yu;
    }

    /// <summary>A reflection turns the sense of rotation about the reflected axis around.</summary>
    protected internal override Twist TransformedBy(Twist by, double u, double v) =>
        new RotationTwist(by.Apply(Axis, u, v), by.Apply(Origin, u, v), by.PreservesOrientation ? Coefficient : -Coefficient, Map);
}
