using RayTracer.Util;

namespace RayTracer.Materials;

/// <summary>Surface response to light; one shading entry point per tracer kind.</summary>
public abstract class Material
{
    public abstract RGBColor Shade(ShadingRecord sr);

    public abstract RGBColor AreaLightShade(ShadingRecord sr);

    public abstract RGBColor PathShade(ShadingRecord sr);

    public abstract RGBColor GlobalShade(ShadingRecord sr);

    /// <summary>Emitted radiance (non-black only for emissive materials).</summary>
    public abstract RGBColor GetLe(ShadingRecord sr);
}
