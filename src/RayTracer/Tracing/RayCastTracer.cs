using RayTracer.Colors;
using RayTracer.Materials;
using RayTracer.Scenes;

namespace RayTracer.Tracing;

/// <summary>Direct lighting only: materials shade with point, directional and ambient lights.</summary>
public sealed class RayCastTracer(World world) : Tracer(world)
{
    protected override RGBColor Shade(Material material, ShadingRecord sr) => material.Shade(sr);
}
