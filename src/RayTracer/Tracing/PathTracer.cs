using RayTracer.Colors;
using RayTracer.Materials;
using RayTracer.Scenes;

namespace RayTracer.Tracing;

/// <summary>
/// Pure path tracing: one sampled bounce per hit, light is only found when a path reaches an emitter or the
/// environment. Unbiased up to the maximum depth, noisy for small lights.
/// </summary>
public sealed class PathTracer(World world) : Tracer(world)
{
    protected override RGBColor Shade(Material material, ShadingRecord sr) => material.PathShade(sr);
}
