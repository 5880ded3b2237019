using Twister;

namespace RayTracer.Viewing;

/// <summary>
/// Projection surfaces of the camera catalogue in the rest frame (eye at the origin, looking along −e3,
/// e2 up), each a Twister cascade of rotations applied to the point straight ahead.
/// </summary>
public static class GpcmSurfaces
{
    private static readonly TwistablePoint Ahead = new(0, 0, -1);

    /// <summary>
    /// The unit sphere for the rectangular mapping: elevation ψ = (2v − 1) ψmax by a turn about e1, then
    /// azimuth λ = (2u − 1) λmax towards image-right by a turn about e2:
    /// (cos ψ sin λ, sin ψ, −cos ψ cos λ). Angles in radians.
    /// </summary>
    public static SingleTwistSurface Sphere(double maxAzimuth, double maxElevation)
    {
        var cascade = TwistCascade.Empty
            .RotateAboutX(1, ParameterMap.Affine(0, 2 * maxElevation, -maxElevation))
            .RotateAboutY(1, ParameterMap.Affine(-2 * maxAzimuth, 0, maxAzimuth));
        return new(Ahead, cascade);
    }

    /// <summary>
    /// The unit cylinder about the e2 axis for the rectangular mapping: the point ahead raised to
    /// height h (v − 1/2), then turned to azimuth λ = (2u − 1) λmax towards image-right about e2:
    /// (sin λ, h (v − 1/2), −cos λ). Angles in radians.
    /// </summary>
    public static SingleTwistSurface Cylinder(double maxAzimuth, double height)
    {
        var cascade = TwistCascade.Empty
            .Translate(new TwistableVector(0, 1, 0), height, ParameterMap.V)
            .RotateAboutY(1, ParameterMap.Affine(-2 * maxAzimuth, 0, maxAzimuth));
        return new(new(0, -height / 2, -1), cascade);
    }

    /// <summary>
    /// A cone about the e2 axis for the rectangular mapping (a conic panorama): v runs up a generatrix of
    /// length <paramref name="slant"/> leaning <paramref name="tilt"/> from vertical towards the axis, with
    /// its middle on the unit circle, then the generatrix is turned to azimuth λ = (2u − 1) λmax about
    /// e2: (r sin λ, s cos τ, −r cos λ) with s = slant (v − 1/2) and r = 1 − s sin τ. A positive tilt
    /// narrows the cone upwards, so upper rows look steeper up and lower rows flatter down than a
    /// cylinder's; zero tilt is the cylinder. Angles in radians.
    /// </summary>
    public static SingleTwistSurface Cone(double maxAzimuth, double slant, double tilt)
    {
        if (!(Math.Abs(tilt) < Math.PI / 2))
            throw new ArgumentOutOfRangeException(nameof(tilt), $"A cone's tilt from vertical must be less than a quarter turn, not {tilt} rad.");
        if (!(slant > 0 && 0.5 * slant * Math.Abs(Math.Sin(tilt)) < 1))
            throw new ArgumentOutOfRangeException(nameof(slant),
                $"A cone of slant {slant} tilted {tilt} rad would pass through its apex; make the image wider or the tilt smaller.");
        var cascade = TwistCascade.Empty
            .Translate(new TwistableVector(0, Math.Cos(tilt), Math.Sin(tilt)), slant, ParameterMap.V)
            .RotateAboutY(1, ParameterMap.Affine(-2 * maxAzimuth, 0, maxAzimuth));
        var half = slant / 2;
        return new(new(0, -half * Math.Cos(tilt), -1 - half * Math.Sin(tilt)), cascade);
    }

    /// <summary>
    /// The unit sphere cap for the polar mapping: the angle from the view axis ψ = v ψmax by a turn about
    /// e2 towards image-right, then the angle α = 2πu about the view axis:
    /// (sin ψ cos α, sin ψ sin α, −cos ψ). A half angle of π/2 is the hemisphere. Angles in radians.
    /// </summary>
    public static SingleTwistSurface Cap(double maxAngleFromAxis)
    {
        var cascade = TwistCascade.Empty
            .RotateAboutY(-maxAngleFromAxis, ParameterMap.V)
            .RotateAboutZ(2 * Math.PI, ParameterMap.U);
        return new(Ahead, cascade);
    }
}
