using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Materials;

/// <summary>
/// Surface response to light, with one shading entry point per tracer kind: <see cref="Shade"/> (ray casting
/// and Whitted), <see cref="AreaLightShade"/> (sampled lights), <see cref="PathShade"/> and <see cref="GlobalShade"/>.
/// </summary>
public abstract class Material
{
    public abstract RGBColor Shade(ShadingRecord sr);

    public virtual RGBColor AreaLightShade(ShadingRecord sr) => Shade(sr);

    public virtual RGBColor PathShade(ShadingRecord sr) => RGBColor.Black;

    /// <summary>Defaults to path shading; materials that add explicit direct light at the first hit override it.</summary>
    public virtual RGBColor GlobalShade(ShadingRecord sr) => PathShade(sr);

    /// <summary>Emitted radiance (non-black only for emissive materials).</summary>
    public virtual RGBColor GetLe(ShadingRecord sr) => RGBColor.Black;

    /// <summary>
    /// Σ over lights of f(wo, wi)·L·(n·wi) [·G / pdf for sampled lights], with shadow rays for lights and
    /// objects that cast shadows. The ambient term is left to the caller.
    /// </summary>
    protected static RGBColor DirectLighting(ShadingRecord sr, Func<ShadingRecord, Vector3D, Vector3D, RGBColor> f, bool sampledLights)
    {
        var world = sr.World ?? throw new InvalidOperationException("Shading record has no world.");
        var wo = -sr.Ray.d.Normalized();
        var sum = RGBColor.Black;
        var lights = world.Lights;
        for (var i = 0; i < lights.Count; i++)
        {
            var light = lights[i];
            var wi = light.GetDirection(sr);
            var ndotwi = sr.Normal.Dot(wi);
            if (ndotwi <= 0)
                continue;
            if (light.CastsShadows && light.InShadow(sr.SpawnRay(wi), sr))
                continue;
            var term = f(sr, wo, wi) * light.L(sr) * ndotwi;
            if (sampledLights)
            {
                var pdf = light.Pdf(sr);
                if (pdf <= 0)
                    continue;
                term = term * (light.G(sr) / pdf);
            }
            sum += term;
        }
        return sum;
    }

    /// <summary>Ambient light of the world times a reflectance (black when there is no ambient light).</summary>
    protected static RGBColor Ambient(ShadingRecord sr, RGBColor rho) =>
        sr.World?.AmbientLight is { } ambient ? rho * ambient.L(sr) : RGBColor.Black;
}
