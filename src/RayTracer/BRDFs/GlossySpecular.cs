using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Sampling;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.BRDFs;

/// <summary>
/// Phong lobe f = ks·cs·(r·wo)^e around the mirror direction r. Sampling draws wi from a cos^e lobe around
/// the mirror direction of wo (Suffern's convention: pdf = lobe·(n·wi), so f·(n·wi)/pdf = ks·cs).
/// </summary>
public sealed class GlossySpecular : BRDF
{
    private Sampler? _sampler;

    private double _exponent;

    public GlossySpecular(double ks = 0.5, double exponent = 20, RGBColor? cs = null)
    {
        Ks = ks;
        _exponent = exponent;
        Color = new ConstantTexture<RGBColor>(cs ?? RGBColor.White);
    }

    public double Ks { get; set; }
    public Texture<RGBColor> Color { get; set; }

    /// <summary>Phong exponent; changing it re-maps the sampler's hemisphere samples (do it before rendering).</summary>
    public double Exponent
    {
        get => _exponent;
        set
        {
            _exponent = value;
            _sampler?.MapSamplesToHemisphere(value);
        }
    }

    /// <summary>Sampler of the reflection lobe; a multi-jittered one is created on first use if none is set.</summary>
    public Sampler Sampler
    {
        get => LazyInitializer.EnsureInitialized(ref _sampler, () =>
        {
            var s = new MultiJitteredSampler(64, seed: SamplerSeeds.Glossy);
            s.MapSamplesToHemisphere(_exponent);
            return s;
        });
        set
        {
            value.MapSamplesToHemisphere(_exponent);
            _sampler = value;
        }
    }

    public override RGBColor F(ShadingRecord sr, Vector3D wo, Vector3D wi)
    {
        var n = sr.Normal;
        var ndotwi = n.Dot(wi);
        var r = -wi + 2.0 * ndotwi * n.ToVector();
        var rdotwo = r.Dot(wo);
        return rdotwo > 0 ? Ks * Math.Pow(rdotwo, Exponent) * Color.GetValue(sr) : RGBColor.Black;
    }

    /// <summary>The density of <see cref="SampleF"/>: lobe·(n·wi), unnormalised as in <see cref="SampleF"/>.</summary>
    public override double Pdf(ShadingRecord sr, Vector3D wo, Vector3D wi)
    {
        var n = sr.Normal;
        var r = -wo + 2.0 * n.Dot(wo) * n.ToVector();
        return Math.Pow(Math.Max(0, r.Dot(wi)), Exponent) * Math.Max(0, n.Dot(wi));
    }

    public override RGBColor SampleF(ShadingRecord sr, Vector3D wo, out Vector3D wi, out double pdf)
    {
        var n = sr.Normal;
        var r = -wo + 2.0 * n.Dot(wo) * n.ToVector();
        var w = r;
        var u = new Vector3D(0.00424, 1, 0.00764).Cross(w).Normalized();
        var v = u.Cross(w);
        var s = Sampler.SampleHemisphere();
        wi = s.x * u + s.y * v + s.z * w;
        if (n.Dot(wi) < 0)
            wi = -s.x * u - s.y * v + s.z * w; // reflect samples that fall below the surface back above it
        var lobe = Math.Pow(Math.Max(0, r.Dot(wi)), Exponent);
        pdf = lobe * Math.Max(0, n.Dot(wi));
        return Ks * lobe * Color.GetValue(sr);
    }
}
