using Twister;

namespace RayTracer.Viewing;

/// <summary>
/// The unit cylinder about the e2 axis for the rectangular mapping: the point ahead raised to
/// height h (v − 1/2), then turned to azimuth λ = (2u − 1) λmax towards image-right about e2:
/// (sin λ, h (v − 1/2), −cos λ). Angles in radians.
/// </summary>
public sealed class CylinderLens : GpcmLens
{
    public CylinderLens(double maxAzimuth, double height) : base(Build(maxAzimuth, height))
    {
        MaxAzimuth = maxAzimuth;
        Height = height;
    }

    public double MaxAzimuth { get; }

    public double Height { get; }

    private static SingleTwistSurface Build(double maxAzimuth, double height)
    {
        var cascade = TwistCascade.Empty
            .Translate(new TwistableVector(0, 1, 0), height, ParameterMap.V)
            .RotateAboutY(1, ParameterMap.Affine(-2 * maxAzimuth, 0, maxAzimuth));
        return new(new(0, -height / 2, -1), cascade);
    }
}
