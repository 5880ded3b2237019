using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Sampling;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.BRDFs;

/// <summary>
/// Perfectly diffuse reflection f = kd·cd / π. The colour may come from a texture (spatially varying).
/// Sampling is cosine-weighted, so f·cos θ / pdf = kd·cd for every sample.
/// </summary>
public sealed class Lambertian : BRDF
{
    private Sampler? _sampler;

    public Lambertian(double kd = 1.0, RGBColor? cd = null)
    {
        Kd = kd;
        Color = new ConstantTexture<RGBColor>(cd ?? RGBColor.White);
    }

    public Lambertian(double kd, Texture<RGBColor> color)
    {
        Kd = kd;
        Color = color;
    }

    public double Kd { get; set; }
    public Texture<RGBColor> Color { get; set; }

    /// <summary>Sampler for indirect bounces; a multi-jittered one is created on first use if none is set.</summary>
    public Sampler Sampler
    {
        get => LazyInitializer.EnsureInitialized(ref _sampler, CreateDefaultSampler); // one instance even if threads race
        set
        {
            value.MapSamplesToHemisphere(1);
            _sampler = value;
        }
    }

    private static Sampler CreateDefaultSampler()
    {
        var s = new MultiJitteredSampler(64, seed: SamplerSeeds.Diffuse);
        s.MapSamplesToHemisphere(1);
        return s;
    }

    public override RGBColor F(ShadingRecord sr, Vector3D wo, Vector3D wi) => Kd * MathConstants.InvPi * Color.GetValue(sr);

    public override RGBColor SampleF(ShadingRecord sr, Vector3D wo, out Vector3D wi, out double pdf)
    {
        var w = sr.Normal.ToVector();
        var v = new Vector3D(0.0034, 1, 0.0071).Cross(w).Normalized();
        var u = v.Cross(w);
        var s = Sampler.SampleHemisphere();
        wi = (s.x * u + s.y * v + s.z * w).Normalized();
        pdf = Math.Max(0, sr.Normal.Dot(wi)) * MathConstants.InvPi;
        return Kd * MathConstants.InvPi * Color.GetValue(sr);
    }

    public override double Pdf(ShadingRecord sr, Vector3D wo, Vector3D wi) => Math.Max(0, sr.Normal.Dot(wi)) * MathConstants.InvPi;

    public override RGBColor Rho(ShadingRecord sr, Vector3D wo) => Kd * Color.GetValue(sr);
}
