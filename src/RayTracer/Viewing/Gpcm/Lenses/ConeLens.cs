using Twister;

namespace RayTracer.Viewing;

/// <summary>
/// A cone about the e2 axis for the rectangular mapping (a conic panorama): v runs up a generatrix of
/// length <see cref="Slant"/> leaning <see cref="Tilt"/> from vertical towards the axis, with its
/// middle on the unit circle, then the generatrix is turned to azimuth λ = (2u − 1) λmax about e2:
/// (r sin λ, s cos τ, −r cos λ) with s = slant (v − 1/2) and r = 1 − s sin τ. A positive tilt
/// narrows the cone upwards, so upper rows look steeper up and lower rows flatter down than a
/// cylinder's; zero tilt is the cylinder. Angles in radians.
/// </summary>
public sealed class ConeLens : GpcmLens
{
    public ConeLens(double maxAzimuth, double slant, double tilt) : base(Build(maxAzimuth, slant, tilt))
    {
        MaxAzimuth = maxAzimuth;
        Slant = slant;
        Tilt = tilt;
        (SinTilt, CosTilt) = Math.SinCos(tilt);
    }

    public double MaxAzimuth { get; }

    public double Slant { get; }

    public double Tilt { get; }

    internal double SinTilt { get; }

    internal double CosTilt { get; }

    private static SingleTwistSurface Build(double maxAzimuth, double slant, double tilt)
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
}
