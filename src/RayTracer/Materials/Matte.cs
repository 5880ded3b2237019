using RayTracer.BRDFs;
using RayTracer.Colors;
using RayTracer.Maths;
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
        _diffuseF = DiffuseBrdf.F;
    }

    // Cached so shading does not allocate a delegate per hit.
    private readonly Func<ShadingRecord, Vector3D, Vector3D, RGBColor> _diffuseF;

    /// <summary>Colour of both the ambient and the diffuse term.</summary>
    public Texture<RGBColor> Color { get; }

    public Lambertian AmbientBrdf { get; }
    public Lambertian DiffuseBrdf { get; }

    public override RGBColor Shade(ShadingRecord sr) =>
        Ambient(sr, AmbientBrdf.Rho(sr, default)) + DirectLighting(sr, _diffuseF, sampledLights: false);

    public override RGBColor AreaLightShade(ShadingRecord sr) =>
        Ambient(sr, AmbientBrdf.Rho(sr, default)) + DirectLighting(sr, _diffuseF, sampledLights: true);

    public override RGBColor PathShade(ShadingRecord sr) => IndirectBounce(sr);

    public override RGBColor GlobalShade(ShadingRecord sr) =>
        sr.Depth == 0 ? AreaLightShade(sr) + IndirectBounce(sr) : IndirectBounce(sr);

    private RGBColor IndirectBounce(ShadingRecord sr)
    {
        var wo = -sr.Ray.d.Normalized();
        var f = DiffuseBrdf.SampleF(sr, wo, out var wi, out var pdf);
        var ndotwi = sr.Normal.Dot(wi);
        if (pdf <= 0 || ndotwi <= 0)
            return RGBColor.Black;
        var tracer = sr.World!.Tracer!;
        return f * tracer.TraceSpawned(sr, sr.SpawnRay(wi), f * (ndotwi / pdf)) * (ndotwi / pdf);
    }
}
