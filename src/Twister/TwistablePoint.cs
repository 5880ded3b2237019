namespace Twister;

/// <summary>A point of 3D space that twists move (lower-case fields, as the GMac class bindings name them).</summary>
public struct TwistablePoint(double x, double y, double z) : ITwistable<TwistablePoint>
{
    public double x = x;
    public double y = y;
    public double z = z;

    public readonly TwistablePoint TwistedBy(Twist twist, double u, double v) => twist.Apply(this, u, v);

    public override readonly string ToString() => FormattableString.Invariant($"({x}, {y}, {z})");
}
