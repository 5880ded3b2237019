namespace Twister;

/// <summary>
/// General reflection in the plane through <see cref="Point"/> with normal <see cref="Normal"/>
/// (thesis §3.9.3, proposed for twists in §8.2.3). It has no parameter: a reflection cannot be
/// reached continuously from the identity.
/// </summary>
public sealed class ReflectionTwist : Twist
{
    private readonly TwistableVector _unit;

    public ReflectionTwist(TwistablePoint point, TwistableVector normal)
    {
        Require.Finite(point, nameof(point));
        _unit = Require.UnitDirection(normal, nameof(normal));
        Point = point;
        Normal = normal;
    }

    public TwistablePoint Point { get; }
    public TwistableVector Normal { get; }

    public override bool PreservesOrientation => false;

    public override bool IgnoresV => true;

    public override TwistablePoint Apply(TwistablePoint p, double u, double v)
    {
        var point = Point;
        var n = _unit;
        var y = new TwistablePoint();

        #region GMac : ReflectionTwistPoint
        //GMac.Bind("p", "Vector3D", point);
        //GMac.Bind("n", "Vector3D", n);
        //GMac.Bind("x", "Vector3D", p);
        //GMac.Bind("y", "Vector3D", y);
        double tmp0 = n.y * (p.y - point.y) + n.z * (p.z - point.z) - point.x * n.x;
        y.x = p.x * (2.0 * (n.y * n.y + n.z * n.z) - 1.0) - 2.0 * n.x * tmp0;
        double tmp1 = -2.0 * (p.x * n.x + tmp0);
        y.y = n.y * tmp1 + p.y;
        y.z = n.z * tmp1 + p.z;
        #endregion

        return y;
    }

    public override TwistableVector Apply(TwistableVector d, double u, double v)
    {
        var point = Point;
        var n = _unit;
        var y = new TwistableVector();

        #region GMac : ReflectionTwistVector
        //GMac.Bind("p", "Vector3D", point);
        //GMac.Bind("n", "Vector3D", n);
        //GMac.Bind("d", "Vector3D", d);
        //GMac.Bind("y", "Vector3D", y);
        double tmp0 = d.z * n.z + d.y * n.y;
        y.x = d.x * (2.0 * (n.y * n.y + n.z * n.z) - 1.0) - 2.0 * n.x * tmp0;
        double tmp1 = -2.0 * (d.x * n.x + tmp0);
        y.y = n.y * tmp1 + d.y;
        y.z = n.z * tmp1 + d.z;
        #endregion

        return y;
    }

    public override TwistableBivector Apply(TwistableBivector b, double u, double v)
    {
        var point = Point;
        var n = _unit;
        var y = new TwistableBivector();

        #region GMac : ReflectionTwistBivector
        //GMac.Bind("p", "Vector3D", point);
        //GMac.Bind("n", "Vector3D", n);
        //GMac.Bind("b", "Bivector3D", b);
        //GMac.Bind("y", "Bivector3D", y);
        double tmp0 = b.zx * n.y + b.xy * n.z;
        double tmp1 = 2.0 * (b.yz * n.x + tmp0);
        y.xy = n.z * tmp1 - b.xy;
        y.yz = b.yz * (1.0 - 2.0 * (n.y * n.y + n.z * n.z)) + 2.0 * n.x * tmp0;
        y.zx = n.y * tmp1 - b.zx;
        #endregion

        return y;
    }

    /// <summary>No parameter, so the product rule has only the J d term.</summary>
    public override void ApplyWithTangents(ref TwistablePoint p, ref TwistableVector du, ref TwistableVector dv, double u, double v)
    {
        p = Apply(p, u, v);
        du = Apply(du, u, v);
        dv = Apply(dv, u, v);
    }

    protected internal override Twist TransformedBy(Twist by, double u, double v) =>
        new ReflectionTwist(by.Apply(Point, u, v), by.Apply(Normal, u, v));
}
