namespace Twister;

/// <summary>
/// A direction of 3D space (a tangent or a normal): twists rotate it but do not translate it.
/// Lower-case fields, as the GMac class bindings name them.
/// </summary>
public struct TwistableVector(double x, double y, double z) : ITwistable<TwistableVector>
{
    public double x = x;
    public double y = y;
    public double z = z;

    public readonly TwistableVector TwistedBy(Twist twist, double u, double v) => twist.Apply(this, u, v);

    public override readonly string ToString() => FormattableString.Invariant($"({x}, {y}, {z})");
}
