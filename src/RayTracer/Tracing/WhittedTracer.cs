using RayTracer.Colors;
using RayTracer.Materials;
using RayTracer.Scenes;

namespace RayTracer.Tracing;

/// <summary>Whitted-style recursion: reflective and transparent materials trace secondary rays up to the maximum depth.</summary>
public sealed class WhittedTracer(World world) : Tracer(world)
{
    protected override RGBColor Shade(Material material, ShadingRecord sr) => material.Shade(sr);
}
