using Twister;

namespace RayTracer.Viewing;

/// <summary>
/// The unit sphere for the rectangular mapping: elevation ψ = (2v − 1) ψmax by a turn about e1, then
/// azimuth λ = (2u − 1) λmax towards image-right by a turn about e2:
/// (cos ψ sin λ, sin ψ, −cos ψ cos λ). Angles in radians.
/// </summary>
public sealed class SphereLens : GpcmLens
{
    private static readonly TwistablePoint Ahead = new(0, 0, -1);

    public SphereLens(double maxAzimuth, double maxElevation) : base(Build(maxAzimuth, maxElevation))
    {
        MaxAzimuth = maxAzimuth;
        MaxElevation = maxElevation;
    }

    public double MaxAzimuth { get; }

    public double MaxElevation { get; }

    private static SingleTwistSurface Build(double maxAzimuth, double maxElevation)
    {
        var cascade = TwistCascade.Empty
            .RotateAboutX(1, ParameterMap.Affine(0, 2 * maxElevation, -maxElevation))
            .RotateAboutY(1, ParameterMap.Affine(-2 * maxAzimuth, 0, maxAzimuth));
        return new(Ahead, cascade);
    }
}
