using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Textures.Noise;

namespace RayTracer.Textures.Solid;

/// <summary>
/// Wood: concentric rings about the y axis whose radius is perturbed by noise, blended between a light and a
/// dark colour, with fine grain from a second, higher-frequency noise.
/// </summary>
public sealed class WoodTexture(LatticeNoise noise, RGBColor light, RGBColor dark, double ringsPerUnit = 4.0, double perturbation = 0.6)
    : SolidTexture<RGBColor>
{
    public LatticeNoise Noise { get; } = noise;
    public RGBColor Light { get; set; } = light;
    public RGBColor Dark { get; set; } = dark;
    public double RingsPerUnit { get; set; } = ringsPerUnit;
    public double Perturbation { get; set; } = perturbation;

    /// <summary>Ring phase in [0, 1): 0 at the start of a light ring.</summary>
    public double RingPhase(Point3D p)
    {
        var r = Math.Sqrt(p.x * p.x + p.z * p.z);
        var wobble = Perturbation * (2 * Noise.Fbm(p.x, 0.25 * p.y, p.z) - 1);
        var rings = (r + wobble / RingsPerUnit) * RingsPerUnit;
        return rings - Math.Floor(rings);
    }

    public override RGBColor Evaluate(Point3D p)
    {
        var phase = RingPhase(p);
        // Smooth light-to-dark profile across a ring, darkest in the middle of the late wood.
        var t = 0.5 - 0.5 * Math.Cos(MathConstants.TwoPi * phase);
        var grain = 0.85 + 0.15 * Noise.Turbulence(8 * p.x, 40 * p.y, 8 * p.z);
        return ((1 - t) * Light + t * Dark) * grain;
    }
}
