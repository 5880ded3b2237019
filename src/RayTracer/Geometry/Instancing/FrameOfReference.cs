using Twister;

namespace RayTracer.Geometry.Instancing;

/// <summary>
/// Two vectors and a point that are moved with an object (thesis §6.6.1): at rest e1, e2 and the
/// origin. Every move goes through Twister twists, so a frame can follow any cascade a curve or a
/// surface uses; <see cref="TsrInstance"/> then reads the translation, rotation and scale off it.
/// Immutable: each move returns a new frame.
/// </summary>
public readonly record struct FrameOfReference(TwistableVector Vx, TwistableVector Vy, TwistablePoint Origin)
{
    public static FrameOfReference Identity { get; } = new(new(1, 0, 0), new(0, 1, 0), default);

    /// <summary>The frame moved by every twist of <paramref name="cascade"/> at the parameters (u, v).</summary>
    public FrameOfReference MovedBy(TwistCascade cascade, double u = 0, double v = 0)
    {
        ArgumentNullException.ThrowIfNull(cascade);
        return new(cascade.Apply(Vx, u, v), cascade.Apply(Vy, u, v), cascade.Apply(Origin, u, v));
    }

    /// <summary>The frame moved by one twist at the parameters (u, v).</summary>
    public FrameOfReference MovedBy(Twist twist, double u = 0, double v = 0)
    {
        ArgumentNullException.ThrowIfNull(twist);
        return new(twist.Apply(Vx, u, v), twist.Apply(Vy, u, v), twist.Apply(Origin, u, v));
    }

    /// <summary>Turned by <paramref name="radians"/> about the line through <paramref name="through"/> along <paramref name="axis"/> (right-handed).</summary>
    public FrameOfReference Rotated(TwistableVector axis, double radians, TwistablePoint through = default) =>
        MovedBy(new RotationTwist(axis, through, radians, ParameterMap.One));

    /// <summary>Scaled by <paramref name="factor"/> &gt; 0 about <paramref name="centre"/>.</summary>
    public FrameOfReference Scaled(double factor, TwistablePoint centre = default) =>
        MovedBy(ScalingTwist.ByFactor(centre, factor));

    public FrameOfReference Translated(TwistableVector by) => MovedBy(new TranslationTwist(by, 1, ParameterMap.One));
}
