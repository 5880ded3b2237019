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
