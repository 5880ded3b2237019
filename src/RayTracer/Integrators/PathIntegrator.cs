using RayTracer.Colors;
using RayTracer.Materials;
using RayTracer.Scenes;
using RayTracer.Tracing;

namespace RayTracer.Integrators;

/// <summary>
/// Pure path tracing: one sampled bounce per hit (the specular lobes, or else the diffuse lobe); light is only
/// found when a path reaches an emitter or the environment. Unbiased up to the maximum depth for diffuse and
/// specular surfaces (a Phong highlight meets lights only, so it is absent here); noisy for small lights.
/// </summary>
public sealed class PathIntegrator(World world) : Integrator(world)
{
    protected override RGBColor Li(Material material, ShadingRecord sr)
    {
        var bsdf = material.GetBsdf(sr);
        return bsdf.IsEmpty ? material.Emitted(sr) : TraceBounce(sr, bsdf, Outgoing(sr));
    }
}
