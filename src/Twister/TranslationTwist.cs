using System.Runtime.CompilerServices;

namespace Twister;

/// <summary>(6.12) translation by t = c_t f_t(u, v) w.</summary>
public sealed class TranslationTwist : Twist
{
    private readonly ScaledMap _theta;

    public TranslationTwist(TwistableVector vector, double coefficient, ParameterMap map)
    {
        Require.Finite(vector, nameof(vector));
        Require.Finite(coefficient, nameof(coefficient));
        Require.NotNull(map, nameof(map));
        Vector = vector;
        Coefficient = coefficient;
        Map = map;
        _theta = new(coefficient, map);
    }

    public TwistableVector Vector { get; }
    public double Coefficient { get; }
    public ParameterMap Map { get; }

    public override bool IgnoresV => Map.IgnoresV;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public override TwistablePoint Apply(TwistablePoint p, double u, double v)
    {
        var w = Vector;
        var theta = _theta.At(u, v);
        var y = new TwistablePoint();

        #region GMac : TranslationTwistPoint
        //GMac.Bind("w", "Vector3D", w);
        //GMac.Bind("theta.1", theta);
        //GMac.Bind("x", "Vector3D", p);
        //GMac.Bind("y", "Vector3D", y);
        y.x = w.x * theta + p.x;
        y.y = w.y * theta + p.y;
        y.z = w.z * theta + p.z;
        #endregion

        return y;
    }

    public override TwistableVector Apply(TwistableVector d, double u, double v) => d;

    public override TwistableBivector Apply(TwistableBivector b, double u, double v) => b;

    public override void ApplyWithTangents(ref TwistablePoint p, ref TwistableVector du, ref TwistableVector dv, double u, double v)
    {
        var w = Vector;
        var theta = _theta.At(u, v);
        var ru = _theta.DerivativeU(u, v);
        var rv = _theta.DerivativeV(u, v);
        TwistablePoint x = p, y = new();
        TwistableVector xu = du, xv = dv, yu = new(), yv = new();

        #region GMac : TranslationTwistPointTangents
        //GMac.Bind("w", "Vector3D", w);
        //GMac.Bind("theta.1", theta);
        //GMac.Bind("ru.1", ru);
        //GMac.Bind("rv.1", rv);
        //GMac.Bind("x", "Vector3D", x);
        //GMac.Bind("du", "Vector3D", xu);
        //GMac.Bind("dv", "Vector3D", xv);
        //GMac.Bind("y", "Vector3D", y);
        //GMac.Bind("yu", "Vector3D", yu);
        //GMac.Bind("yv", "Vector3D", yv);
        y.x = w.x * theta + x.x;
        y.y = w.y * theta + x.y;
        y.z = w.z * theta + x.z;
        yu.x = w.x * ru + xu.x;
        yu.y = w.y * ru + xu.y;
        yu.z = xu.z + w.z * ru;
        yv.x = w.x * rv + xv.x;
        yv.y = w.y * rv + xv.y;
        yv.z = xv.z + w.z * rv;
        #endregion

        p = y;
        du = yu;
        dv = yv;
    }

    protected internal override Twist TransformedBy(Twist by, double u, double v) =>
        new TranslationTwist(by.Apply(Vector, u, v), Coefficient, Map);
}
