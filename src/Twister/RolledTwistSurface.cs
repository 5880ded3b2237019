namespace Twister;

/// <summary>
/// Two curves in u joined by a segment in v (thesis §6.4.1): S(u, v) is the point at v along the
/// segment from C1(u) to C2(u), a translation by v (C2(u) − C1(u)) applied to C1(u).
/// </summary>
public sealed class RolledTwistSurface : IParametricSurface
{
    public RolledTwistSurface(TwistCurve first, TwistCurve second)
    {
        Require.NotNull(first, nameof(first));
        Require.NotNull(second, nameof(second));
        First = first;
        Second = second;
    }

    public TwistCurve First { get; }
    public TwistCurve Second { get; }

    public TwistablePoint PointAt(double u, double v) => Evaluate(u, v, out _, out _);

    public TwistableBivector TangentPlaneAt(double u, double v)
    {
        Evaluate(u, v, out var su, out var sv);
        return TwistableBivector.Span(su, sv);
    }

    /// <summary>N = B ⌋ I3⁻¹ (6.10).</summary>
    public TwistableVector NormalAt(double u, double v) => TangentPlaneAt(u, v).Normal();

    private TwistablePoint Evaluate(double u, double v, out TwistableVector su, out TwistableVector sv)
    {
        Require.Parameters(u, v);
        var p1 = First.PointAndTangentAt(u, out var t1);
        var p2 = Second.PointAndTangentAt(u, out var t2);
        TwistablePoint s = new();
        TwistableVector gu = new(), gv = new();

        #region GMac : RolledSurfacePoint
        //GMac.Bind("p1", "Vector3D", p1);
        //GMac.Bind("p2", "Vector3D", p2);
        //GMac.Bind("t1", "Vector3D", t1);
        //GMac.Bind("t2", "Vector3D", t2);
        //GMac.Bind("v.1", v);
        //GMac.Bind("s", "Vector3D", s);
        //GMac.Bind("su", "Vector3D", gu);
        //GMac.Bind("sv", "Vector3D", gv);
        double tmp0 = 1.0 - v;
        s.x = p1.x * tmp0 + v * p2.x;
        s.y = p1.y * tmp0 + v * p2.y;
        s.z = p1.z * tmp0 + v * p2.z;
        gu.x = t1.x * tmp0 + v * t2.x;
        gu.y = t1.y * tmp0 + t2.y * v;
        gu.z = t1.z * tmp0 + t2.z * v;
        gv.x = p2.x - p1.x;
        gv.y = p2.y - p1.y;
        gv.z = p2.z - p1.z;
        #endregion

        su = gu;
        sv = gv;
        return s;
    }
}
