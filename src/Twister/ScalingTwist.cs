namespace Twister;

/// <summary>
/// Uniform scaling about <see cref="Centre"/> by the factor e^θ, θ = c_s f_s(u, v) (thesis (3.95),
/// §3.9.3, proposed for twists in §8.2.3). The exponent keeps θ = 0 the identity like every other
/// twist, and every θ a valid (positive) factor; <see cref="ByFactor"/> takes a plain factor.
/// </summary>
public sealed class ScalingTwist : Twist
{
    public ScalingTwist(TwistablePoint centre, double coefficient, ParameterMap map)
    {
        Require.Finite(centre, nameof(centre));
        Require.Finite(coefficient, nameof(coefficient));
        Require.NotNull(map, nameof(map));
        Centre = centre;
        Coefficient = coefficient;
        Map = map;
    }

    /// <summary>A constant scaling by <paramref name="factor"/> &gt; 0.</summary>
    public static ScalingTwist ByFactor(TwistablePoint centre, double factor)
    {
        if (!(factor > 0) || !double.IsFinite(factor))
            throw new ArgumentException($"'{nameof(factor)}' must be a finite number above 0, not {factor}", nameof(factor));
        return new(centre, Math.Log(factor), ParameterMap.One);
    }

    public TwistablePoint Centre { get; }
    public double Coefficient { get; }
    public ParameterMap Map { get; }

    public override bool IgnoresV => Map.IgnoresV;

    public override TwistablePoint Apply(TwistablePoint p, double u, double v)
    {
        var c = Centre;
        var theta = Exponent(u, v);
        var y = new TwistablePoint();

        #region GMac : ScalingTwistPoint
        //GMac.Bind("c", "Vector3D", c);
        //GMac.Bind("theta.1", theta);
        //GMac.Bind("x", "Vector3D", p);
        //GMac.Bind("y", "Vector3D", y);
        double tmp0 = Math.Exp(theta);
        double tmp1 = tmp0 - 1.0;
        y.x = p.x * tmp0 - c.x * tmp1;
        y.y = p.y * tmp0 - c.y * tmp1;
        y.z = p.z * tmp0 - c.z * tmp1;
        #endregion

        return y;
    }

    public override TwistableVector Apply(TwistableVector d, double u, double v)
    {
        var c = Centre;
        var theta = Exponent(u, v);
        var y = new TwistableVector();

        #region GMac : ScalingTwistVector
        //GMac.Bind("c", "Vector3D", c);
        //GMac.Bind("theta.1", theta);
        //GMac.Bind("d", "Vector3D", d);
        //GMac.Bind("y", "Vector3D", y);
        double tmp0 = Math.Exp(theta);
        y.x = d.x * tmp0;
        y.y = d.y * tmp0;
        y.z = d.z * tmp0;
        #endregion

        return y;
    }

    public override TwistableBivector Apply(TwistableBivector b, double u, double v)
    {
        var c = Centre;
        var theta = Exponent(u, v);
        var y = new TwistableBivector();

        #region GMac : ScalingTwistBivector
        //GMac.Bind("c", "Vector3D", c);
        //GMac.Bind("theta.1", theta);
        //GMac.Bind("b", "Bivector3D", b);
        //GMac.Bind("y", "Bivector3D", y);
        double tmp0 = Math.Exp(2.0 * theta);
        y.xy = b.xy * tmp0;
        y.yz = b.yz * tmp0;
        y.zx = b.zx * tmp0;
        #endregion

        return y;
    }

    public override void ApplyWithTangents(ref TwistablePoint p, ref TwistableVector du, ref TwistableVector dv, double u, double v)
    {
        var c = Centre;
        var theta = Exponent(u, v);
        var ru = Coefficient * Map.DerivativeU(u, v);
        var rv = Coefficient * Map.DerivativeV(u, v);
        TwistablePoint x = p, y = new();
        TwistableVector xu = du, xv = dv, yu = new(), yv = new();

        #region GMac : ScalingTwistPointTangents
        //GMac.Bind("c", "Vector3D", c);
        //GMac.Bind("theta.1", theta);
        //GMac.Bind("ru.1", ru);
        //GMac.Bind("rv.1", rv);
        //GMac.Bind("x", "Vector3D", x);
        //GMac.Bind("du", "Vector3D", xu);
        //GMac.Bind("dv", "Vector3D", xv);
        //GMac.Bind("y", "Vector3D", y);
        //GMac.Bind("yu", "Vector3D", yu);
        //GMac.Bind("yv", "Vector3D", yv);
        double tmp0 = Math.Exp(theta);
        double tmp1 = tmp0 - 1.0;
        y.x = x.x * tmp0 - c.x * tmp1;
        y.y = x.y * tmp0 - c.y * tmp1;
        y.z = x.z * tmp0 - c.z * tmp1;
        double tmp2 = x.x - c.x;
        yu.x = tmp0 * (tmp2 * ru + xu.x);
        double tmp3 = c.y - x.y;
        yu.y = tmp0 * (xu.y - tmp3 * ru);
        double tmp4 = c.z - x.z;
        yu.z = tmp0 * (xu.z - tmp4 * ru);
        yv.x = tmp0 * (tmp2 * rv + xv.x);
        yv.y = tmp0 * (xv.y - tmp3 * rv);
        yv.z = tmp0 * (xv.z - tmp4 * rv);
        #endregion

        p = y;
        du = yu;
        dv = yv;
    }

    protected internal override Twist TransformedBy(Twist by, double u, double v) =>
        new ScalingTwist(by.Apply(Centre, u, v), Coefficient, Map);

    /// <summary>θ, refused beyond the range where e^θ is a finite non-zero factor.</summary>
    private double Exponent(double u, double v)
    {
        var theta = Coefficient * Map.Evaluate(u, v);
        if (Math.Abs(theta) > 700)
            throw new ArgumentException(FormattableString.Invariant($"the scaling factor e^{theta} at (u, v) = ({u}, {v}) is out of range"), nameof(u));
        return theta;
    }
}
