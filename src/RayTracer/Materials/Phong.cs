using RayTracer.BRDFs;
using RayTracer.Colors;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.Materials;

/// <summary>
/// Diffuse plus a glossy highlight (Lambertian + Phong lobe). The diffuse colour is a texture, so a
/// spatially varying Phong is this class too; a plain colour is a constant texture. The highlight meets
/// lights only: a path bounce samples the diffuse lobe. Subclasses add specular lobes.
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
    }

    /// <summary>Colour of the ambient and diffuse terms (the highlight has its own).</summary>
    public Texture<RGBColor> Color { get; }

    public Lambertian AmbientBrdf { get; }
    public Lambertian DiffuseBrdf { get; }
    public GlossySpecular SpecularBrdf { get; }

    /// <summary>Lobes traced by the integrators on top of the diffuse and highlight ones (none for plain Phong).</summary>
    protected virtual SpecularScattering? Specular => null;

    public override Bsdf GetBsdf(ShadingRecord sr) => new(sr, DiffuseBrdf, SpecularBrdf, Specular);

    public override RGBColor AmbientReflectance(ShadingRecord sr) => AmbientBrdf.Rho(sr, default);
}
