using RayTracer.BRDFs;
using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.Materials;

/// <summary>
/// Diffuse plus a glossy highlight (Lambertian + Phong lobe). The diffuse colour is a texture, so a
/// spatially varying Phong is this class too; a plain colour is a constant texture.
/// </summary>
public class Phong : Material
{
    public Phong(double ka = 0.25, double kd = 0.6, RGBColor? cd = null, double ks = 0.2, double exponent = 20, RGBColor? cs = null)
        : this(ka, kd, new ConstantTexture<RGBColor>(cd ?? RGBColor.White), ks, exponent, cs)
    {
    }

    public Phong(double ka, double kd, Texture<RGBColor> color, double ks, double exponent, RGBColor? cs = null)
    {
        Color = color;
        AmbientBrdf = new Lambertian(ka, color);
        DiffuseBrdf = new Lambertian(kd, color);
        SpecularBrdf = new GlossySpecular(ks, exponent, cs ?? RGBColor.White);
        _f = DiffusePlusSpecular;
    }

    // Cached so shading does not allocate a delegate per hit.
    private readonly Func<ShadingRecord, Vector3D, Vector3D, RGBColor> _f;

    /// <summary>Colour of the ambient and diffuse terms (the highlight has its own).</summary>
    public Texture<RGBColor> Color { get; }

    public Lambertian AmbientBrdf { get; }
    public Lambertian DiffuseBrdf { get; }
    public GlossySpecular SpecularBrdf { get; }

    private RGBColor DiffusePlusSpecular(ShadingRecord sr, Vector3D wo, Vector3D wi) =>
        DiffuseBrdf.F(sr, wo, wi) + SpecularBrdf.F(sr, wo, wi);

    public override RGBColor Shade(ShadingRecord sr) =>
        Ambient(sr, AmbientBrdf.Rho(sr, default)) + DirectLighting(sr, _f, sampledLights: false);

    public override RGBColor AreaLightShade(ShadingRecord sr) =>
        Ambient(sr, AmbientBrdf.Rho(sr, default)) + DirectLighting(sr, _f, sampledLights: true);

    /// <summary>Diffuse bounce only; the highlight is a direct-lighting effect.</summary>
    public override RGBColor PathShade(ShadingRecord sr)
    {
        var wo = -sr.Ray.d.Normalized();
        var f = DiffuseBrdf.SampleF(sr, wo, out var wi, out var pdf);
        var ndotwi = sr.Normal.Dot(wi);
        if (pdf <= 0 || ndotwi <= 0)
            return RGBColor.Black;
        return f * sr.World!.Tracer!.TraceSpawned(sr, sr.SpawnRay(wi), f * (ndotwi / pdf)) * (ndotwi / pdf);
    }

    public override RGBColor GlobalShade(ShadingRecord sr) =>
        sr.Depth == 0 ? AreaLightShade(sr) + PathShade(sr) : PathShade(sr);
}
