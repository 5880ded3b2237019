using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Sampling;
using RayTracer.Tracing;

namespace RayTracer.Lights;

/// <summary>
/// Ambient light that is dimmed where the hemisphere above a point is blocked: one cosine-distributed
/// shadow ray per call; occluded points receive <see cref="MinAmount"/> of the light instead of all of it.
/// </summary>
public sealed class AmbientOccluder : Light
{
    private readonly Sampler _sampler;

    public AmbientOccluder(Sampler sampler, double radianceScale = 1.0, RGBColor? color = null, double minAmount = 0.0)
    {
        _sampler = sampler;
        _sampler.MapSamplesToHemisphere(1);
        RadianceScale = radianceScale;
        Color = color ?? RGBColor.White;
        MinAmount = minAmount;
    }

    public double RadianceScale { get; set; }
    public RGBColor Color { get; set; }
    public double MinAmount { get; set; }

    /// <summary>Orthonormal frame with w along <paramref name="n"/>; the jittered up vector avoids degeneracy at the poles.</summary>
    public static (Vector3D U, Vector3D V, Vector3D W) Frame(Normal3D n)
    {
        var w = n.ToVector();
        var v = new Vector3D(0.0072, 1.0, 0.0034).Cross(w);
        v.Normalize();
        var u = v.Cross(w);
        return (u, v, w);
    }

    public override Vector3D GetDirection(ShadingRecord sr)
    {
        var (u, v, w) = Frame(sr.Normal);
        var s = _sampler.SampleHemisphere();
        return s.x * u + s.y * v + s.z * w;
    }

    public override bool SamplesVisibility => true;

    /// <summary>Radiance where the sampled direction is open.</summary>
    public override RGBColor L(ShadingRecord sr) => RadianceScale * Color;

    /// <summary>Radiance where the sampled direction is blocked: <see cref="MinAmount"/> of it.</summary>
    public override RGBColor ShadowedL(ShadingRecord sr) => MinAmount * RadianceScale * Color;
}
