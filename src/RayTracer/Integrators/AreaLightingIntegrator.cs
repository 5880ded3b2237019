using RayTracer.Scenes;

namespace RayTracer.Integrators;

/// <summary>Direct lighting with area and environment lights estimated by sampling (soft shadows), plus the specular lobes.</summary>
public sealed class AreaLightingIntegrator(World world) : WhittedIntegrator(world)
{
    protected override bool SampledLights => true;
}
