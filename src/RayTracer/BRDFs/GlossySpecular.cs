using RayTracer.Sampling;
using RayTracer.Textures;
using RayTracer.Util;

namespace RayTracer.BRDFs;

/// <summary>
/// Phong lobe f = ks·cs·(r·wo)^e around the mirror direction r. Sampling draws wi from a cos^e lobe around
/// the mirror direction of wo (Suffern's convention: pdf = lobe·(n·wi), so f·(n·wi)/pdf = ks·cs).
/// </summary>
public sealed class GlossySpecular : BRDF
{
    private Sampler? _sampler;

    public GlossySpecular(double ks = 0.5, double exponent = 20, RGBColor? cs = null)
    {
        Ks = ks;
        Exponent = exponent;
        Color = new ConstantTexture<RGBColor>(cs ?? RGBColor.White);
    }

    public double Ks { get; set; }
    public double Exponent { get; set; }
    public Texture<RGBColor> Color { get; set; }

    public Sampler Sampler
    {
        get
        {
            if (_sampler is null || _sampler.HemisphereExponent != Exponent)
            {
                var s = _sampler ?? new MultiJitteredSampler(64);
                s.MapSamplesToHemisphere(Exponent);
                _sampler = s;
            }
            return _sampler;
        }
        set
        {
            value.MapSamplesToHemisphere(Exponent);
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
