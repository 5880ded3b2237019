using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Sampling;
using RayTracer.Tracing;

namespace RayTracer.Lights;

/// <summary>
/// Uniform light from the sphere at infinity. Directions are sampled cosine-weighted around the normal,
/// so the estimator's cos θ / pdf is π. Set it as <c>World.Environment</c> too so escaping rays see it.
/// </summary>
public sealed class EnvironmentLight : Light
{
    private readonly Sampler _sampler;

    public EnvironmentLight(Sampler sampler, double radianceScale = 1.0, RGBColor? color = null)
    {
        _sampler = sampler;
        _sampler.MapSamplesToHemisphere(1);
        RadianceScale = radianceScale;
        Color = color ?? RGBColor.White;
    }

    public double RadianceScale { get; set; }
    public RGBColor Color { get; set; }

    /// <summary>Radiance arriving from direction -<paramref name="direction"/> (uniform here).</summary>
    public RGBColor Radiance(Vector3D direction) => RadianceScale * Color;

    public override Vector3D GetDirection(ShadingRecord sr)
    {
        var (u, v, w) = AmbientOccluder.Frame(sr.Normal);
        var s = _sampler.SampleHemisphere();
        var wi = s.x * u + s.y * v + s.z * w;
        sr.Direction = wi;
        return wi;
    }

    public override RGBColor L(ShadingRecord sr) => RadianceScale * Color;


    public override double Pdf(ShadingRecord sr) => Math.Max(0, sr.Normal.Dot(sr.Direction)) * MathConstants.InvPi;
}
