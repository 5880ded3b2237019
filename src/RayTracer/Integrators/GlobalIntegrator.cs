using RayTracer.Colors;
using RayTracer.Materials;
using RayTracer.Scenes;
using RayTracer.Tracing;

namespace RayTracer.Integrators;

/// <summary>
/// Path tracing with explicit direct lighting at the first hit of opaque surfaces (sampled lights); emitters
/// seen one bounce later are skipped so their light is not counted twice. Surfaces that transmit rely on
/// their traced rays alone.
/// </summary>
public sealed class GlobalIntegrator(World world) : Integrator(world)
{
    protected override RGBColor Li(Material material, ShadingRecord sr)
    {
        var bsdf = material.GetBsdf(sr);
        if (bsdf.IsEmpty)
            return sr.Depth == 1 ? RGBColor.Black : material.Emitted(sr);
        var wo = Outgoing(sr);
        if (sr.Depth == 0 && !bsdf.Transmits)
            return Reflected(material, sr, bsdf, wo, sampledLights: true) + TraceBounce(sr, bsdf, wo);
        return TraceBounce(sr, bsdf, wo);
    }
}
