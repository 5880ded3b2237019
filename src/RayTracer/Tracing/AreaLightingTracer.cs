using RayTracer.Colors;
using RayTracer.Materials;
using RayTracer.Scenes;

namespace RayTracer.Tracing;

/// <summary>Direct lighting with area and environment lights estimated by sampling (soft shadows).</summary>
public sealed class AreaLightingTracer(World world) : Tracer(world)
{
    protected override RGBColor Shade(Material material, ShadingRecord sr) => material.AreaLightShade(sr);
}
