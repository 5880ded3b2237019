using RayTracer.Colors;
using RayTracer.Materials;
using RayTracer.Scenes;
using RayTracer.Tracing;

namespace RayTracer.Integrators;

/// <summary>
/// Whitted-style ray tracing: ambient and direct light from point, directional and ambient lights (area
/// lights at their sampled point, without the density), plus the specular lobes traced recursively up to
/// the maximum depth.
/// </summary>
public class WhittedIntegrator(World world) : Integrator(world)
{
    protected virtual bool SampledLights => false;

    protected override RGBColor Li(Material material, ShadingRecord sr)
    {
        var bsdf = material.GetBsdf(sr);
        if (bsdf.IsEmpty)
            return material.Emitted(sr);
        var wo = Outgoing(sr);
        var reflected = Reflected(material, sr, bsdf, wo, SampledLights);
        return bsdf.HasSpecular ? reflected + TraceSpecular(sr, bsdf, wo) : reflected;
    }
}
