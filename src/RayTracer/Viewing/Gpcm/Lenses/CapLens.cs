using Twister;

namespace RayTracer.Viewing;

/// <summary>
/// The unit sphere cap for the polar mapping: the angle from the view axis ψ = v ψmax by a turn about
/// e2 towards image-right, then the angle α = 2πu about the view axis:
/// (sin ψ cos α, sin ψ sin α, −cos ψ). A half angle of π/2 is the hemisphere. Angles in radians.
/// </summary>
public sealed class CapLens : GpcmLens
{
    private static readonly TwistablePoint Ahead = new(0, 0, -1);

    public CapLens(double maxAngleFromAxis) : base(Build(maxAngleFromAxis)) => MaxAngleFromAxis = maxAngleFromAxis;

    public double MaxAngleFromAxis { get; }

    private static SingleTwistSurface Build(double maxAngleFromAxis)
    {
        var cascade = TwistCascade.Empty
            .RotateAboutY(-maxAngleFromAxis, ParameterMap.V)
            .RotateAboutZ(2 * Math.PI, ParameterMap.U);
        return new(Ahead, cascade);
    }
}
