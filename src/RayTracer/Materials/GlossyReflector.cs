using RayTracer.BRDFs;
using RayTracer.Colors;
using RayTracer.Tracing;

namespace RayTracer.Materials;

/// <summary>Phong plus blurred reflection: one sampled ray from a Phong lobe around the mirror direction.</summary>
public sealed class GlossyReflector : Phong
{
    public GlossyReflector(double ka = 0.0, double kd = 0.0, RGBColor? cd = null, double ks = 0.0, double exponent = 100,
        double kr = 0.75, RGBColor? cr = null)
        : base(ka, kd, cd, ks, exponent)
    {
        GlossyBrdf = new GlossySpecular(kr, exponent, cr ?? RGBColor.White);
    }

    public GlossySpecular GlossyBrdf { get; }

    private RGBColor BlurredReflection(ShadingRecord sr)
    {
        var wo = -sr.Ray.d.Normalized();
        var fr = GlossyBrdf.SampleF(sr, wo, out var wi, out var pdf);
        if (pdf <= 0)
            return RGBColor.Black;
        var ndotwi = sr.Normal.Dot(wi);
        return fr * sr.World!.Tracer!.TraceSpawned(sr, sr.SpawnRay(wi), fr * (ndotwi / pdf)) * (ndotwi / pdf);
    }

    public override RGBColor Shade(ShadingRecord sr) => base.Shade(sr) + BlurredReflection(sr);

    public override RGBColor AreaLightShade(ShadingRecord sr) => base.AreaLightShade(sr) + BlurredReflection(sr);

    public override RGBColor PathShade(ShadingRecord sr) => BlurredReflection(sr);

    public override RGBColor GlobalShade(ShadingRecord sr) =>
        sr.Depth == 0 ? base.AreaLightShade(sr) + BlurredReflection(sr) : BlurredReflection(sr);
}
