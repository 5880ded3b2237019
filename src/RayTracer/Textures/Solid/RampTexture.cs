using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Textures.Noise;

namespace RayTracer.Textures.Solid;

/// <summary>
/// Marble: colours looked up in a ramp at (1 + sin(y·frequency + amplitude·fBm)) / 2, so bands along y are
/// bent by noise.
/// </summary>
public sealed class RampTexture : SolidTexture<RGBColor>
{
    private readonly RGBColor[] _ramp;

    public RampTexture(LatticeNoise noise, IReadOnlyList<RGBColor> ramp, double amplitude = 2.0, double frequency = 4.0)
    {
        if (ramp.Count < 2)
            throw new ArgumentException("A colour ramp needs at least two colours.", nameof(ramp));
        Noise = noise;
        _ramp = ramp.ToArray();
        Amplitude = amplitude;
        Frequency = frequency;
    }

    public LatticeNoise Noise { get; }
    public double Amplitude { get; set; }
    public double Frequency { get; set; }

    /// <summary>Piecewise-linear lookup of the ramp at t in [0, 1].</summary>
    public RGBColor Lookup(double t)
    {
        var x = Math.Clamp(t, 0, 1) * (_ramp.Length - 1);
        var i = Math.Min((int)x, _ramp.Length - 2);
        var f = x - i;
        return (1 - f) * _ramp[i] + f * _ramp[i + 1];
    }

    public override RGBColor Evaluate(Point3D p)
    {
        var fbm = Noise.Fbm(p.x, p.y, p.z);
        return Lookup(0.5 * (1 + Math.Sin(p.y * Frequency + Amplitude * fbm)));
    }
}
