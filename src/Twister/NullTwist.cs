namespace Twister;

/// <summary>The identity twist: every input comes back unchanged.</summary>
public sealed class NullTwist : Twist
{
    public static NullTwist Instance { get; } = new();

    private NullTwist() { }

    public override bool IgnoresV => true;

    public override TwistablePoint Apply(TwistablePoint p, double u, double v) => p;
    public override TwistableVector Apply(TwistableVector d, double u, double v) => d;
    public override TwistableBivector Apply(TwistableBivector b, double u, double v) => b;

    public override void ApplyWithTangents(ref TwistablePoint p, ref TwistableVector du, ref TwistableVector dv, double u, double v) { }

    protected internal override Twist TransformedBy(Twist by, double u, double v) => this;
}
