using RayTracer.Colors;
using RayTracer.Materials;
using RayTracer.Scenes;

namespace RayTracer.Tracing;

/// <summary>
/// Path tracing with explicit direct lighting at the first hit: emitters seen after the first diffuse
/// bounce are skipped so their light is not counted twice.
/// </summary>
public sealed class GlobalTracer(World world) : Tracer(world)
{
    protected override RGBColor Shade(Material material, ShadingRecord sr) => material.GlobalShade(sr);
}
