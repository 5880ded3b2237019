namespace Twister;

/// <summary>
/// Something a twist moves (thesis Figure 6-2): points, directions, tangent bivectors and other twists.
/// (u, v) are the parameters at which the twist's parameter maps are evaluated.
/// </summary>
public interface ITwistable<TSelf> where TSelf : ITwistable<TSelf>
{
    TSelf TwistedBy(Twist twist, double u, double v);
}
