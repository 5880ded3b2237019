using RayTracer.BRDFs;
using RayTracer.Colors;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.Materials;

/// <summary>
/// Diffuse surface: Lambertian ambient and diffuse terms with a shared colour. The colour is a texture,
/// so a spatially varying matte is this class too; a plain colour is a constant texture.
/// </summary>
public class Matte : Material
{
    public Matte(double ka = 0.25, double kd = 0.75, RGBColor? cd = null)
        : this(ka, kd, new ConstantTexture<RGBColor>(cd ?? RGBColor.White))
    {
    }

    public Matte(double ka, double kd, Texture<RGBColor> color)
    {
        Color = color;
        AmbientBrdf = new Lambertian(ka, color);
        DiffuseBrdf = new Lambertian(kd, color);
    }

    /// <summary>Colour of both the ambient and the diffuse term.</summary>
    public Texture<RGBColor> Color { get; }

    public Lambertian AmbientBrdf { get; }
    public Lambertian DiffuseBrdf { get; }

    public override Bsdf GetBsdf(ShadingRecord sr) => new(sr, DiffuseBrdf);

    public override RGBColor AmbientReflectance(ShadingRecord sr) => AmbientBrdf.Rho(sr, default);
}
