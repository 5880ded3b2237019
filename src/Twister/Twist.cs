namespace Twister;

/// <summary>
/// A Euclidean transform (or a uniform scaling) whose versor depends on the parameters (u, v) through
/// parameter maps (thesis §6.4.1, Figure 6-3). It applies to points, directions, tangent bivectors and
/// other twists; every application is a kernel generated from dsl/macros/twister.gmac.
/// </summary>
public abstract class Twist : ITwistable<Twist>
{
    /// <summary>False for reflections: they turn a right-handed frame into a left-handed one.</summary>
    public virtual bool PreservesOrientation => true;

    /// <summary>True when no parameter map of the twist depends on v, so it can drive a curve.</summary>
    public abstract bool IgnoresV { get; }

    public abstract TwistablePoint Apply(TwistablePoint p, double u, double v);

    /// <summary>Moves a direction (a tangent); translations leave it alone.</summary>
    public abstract TwistableVector Apply(TwistableVector d, double u, double v);

    /// <summary>Moves a tangent plane as the two tangents spanning it.</summary>
    public abstract TwistableBivector Apply(TwistableBivector b, double u, double v);

    /// <summary>
    /// One step of the product rule: <paramref name="p"/> moves to T(p), and each tangent d moves to
    /// J d + ∂T(p)/∂θ · ∂θ/∂u (or ∂v), θ the twist's parameters.
    /// </summary>
    public abstract void ApplyWithTangents(ref TwistablePoint p, ref TwistableVector du, ref TwistableVector dv, double u, double v);

    /// <summary>
    /// <see cref="ApplyWithTangents"/> for one tangent (a curve's ∂/∂u): twists whose two-tangent
    /// kernel is costly override it with a kernel that leaves the second tangent out.
    /// </summary>
    public virtual void ApplyWithTangent(ref TwistablePoint p, ref TwistableVector du, double u, double v)
    {
        var dv = default(TwistableVector);
        ApplyWithTangents(ref p, ref du, ref dv, u, v);
    }

    /// <summary>
    /// This twist applied to another (at the parameters (u, v) of this one): the other's axis, origin
    /// and direction move with it, so that <c>result.Apply(Apply(p))</c> equals <c>Apply(other.Apply(p))</c>.
    /// </summary>
    public Twist Apply(Twist other, double u = 0, double v = 0)
    {
        Require.NotNull(other, nameof(other));
        return other.TransformedBy(this, u, v);
    }

    public Twist TwistedBy(Twist twist, double u, double v) => twist.Apply(this, u, v);

    /// <summary>This twist conjugated by <paramref name="by"/> evaluated at (u, v).</summary>
    protected internal abstract Twist TransformedBy(Twist by, double u, double v);

    public Twist RotatedAboutX(double angle) => RotationTwist.AboutX(angle, ParameterMap.One).Apply(this);
    public Twist RotatedAboutY(double angle) => RotationTwist.AboutY(angle, ParameterMap.One).Apply(this);
    public Twist RotatedAboutZ(double angle) => RotationTwist.AboutZ(angle, ParameterMap.One).Apply(this);
    public Twist TranslatedBy(TwistableVector offset) => new TranslationTwist(offset, 1, ParameterMap.One).Apply(this);
}
