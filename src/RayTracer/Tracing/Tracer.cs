using RayTracer.Materials;
using RayTracer.Scenes;
using RayTracer.Util;

namespace RayTracer.Tracing;

/// <summary>
/// Computes the radiance carried back along a ray: finds the nearest hit and asks its material for one
/// of its shading entry points. Beyond the view plane's maximum depth a ray carries nothing.
/// </summary>
public abstract class Tracer
{
    protected Tracer(World world)
    {
        World = world;
    }

    public World World { get; }

    public RGBColor TraceRay(in Ray ray, int depth) => TraceRay(ray, depth, out _);

    /// <summary>Also returns the distance to the hit (<see cref="MathConstants.HugeValue"/> on a miss), for Beer's law.</summary>
    public RGBColor TraceRay(in Ray ray, int depth, out double tmin)
    {
        tmin = MathConstants.HugeValue;
        if (depth > World.ViewPlane.MaxDepth)
            return RGBColor.Black;
        var sr = World.HitObjects(ray);
        if (!sr.HitAnObject || sr.Material is null)
            return World.BackgroundRadiance(ray);
        sr.Depth = depth;
        sr.Ray = ray;
        tmin = sr.T;
        return Shade(sr.Material, sr);
    }

    protected abstract RGBColor Shade(Material material, ShadingRecord sr);
}
