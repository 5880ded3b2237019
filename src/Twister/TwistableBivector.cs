namespace Twister;

/// <summary>
/// A tangent plane (thesis §6.3.1): the bivector xy e1^e2 + yz e2^e3 + zx e3^e1, e.g. B = ∂S/∂u ^ ∂S/∂v.
/// It moves as the two tangents that span it; its normal is B ⌋ I3⁻¹ = (yz, zx, xy).
/// </summary>
public struct TwistableBivector(double xy, double yz, double zx) : ITwistable<TwistableBivector>
{
    public double xy = xy;
    public double yz = yz;
    public double zx = zx;

    /// <summary>(6.10) B = a ^ b.</summary>
    public static TwistableBivector Span(TwistableVector a, TwistableVector b)
    {
        var result = new TwistableBivector();

        #region GMac : TangentPlane
        //GMac.Bind("su", "Vector3D", a);
        //GMac.Bind("sv", "Vector3D", b);
        //GMac.Bind("b", "Bivector3D", result);
        result.xy = a.x * b.y - a.y * b.x;
        result.yz = a.y * b.z - a.z * b.y;
        result.zx = a.z * b.x - a.x * b.z;
        #endregion

        return result;
    }

    /// <summary>(6.10) N = B ⌋ I3⁻¹.</summary>
    public readonly TwistableVector Normal()
    {
        var b = this;
        var n = new TwistableVector();

        #region GMac : NormalOfBivector
        //GMac.Bind("a", "Bivector3D", b);
        //GMac.Bind("n", "Vector3D", n);
        n.x = b.yz;
        n.y = b.zx;
        n.z = b.xy;
        #endregion

        return n;
    }

    public readonly TwistableBivector TwistedBy(Twist twist, double u, double v) => twist.Apply(this, u, v);

    public override readonly string ToString() => FormattableString.Invariant($"({xy}, {yz}, {zx})");
}
