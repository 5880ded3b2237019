using RayTracer.Colors;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Scenes;

namespace RayTracer.Tracing;

/// <summary>
/// Computes the radiance carried back along a ray: finds the nearest hit and asks its material for one
/// of its shading entry points. Beyond the view plane's maximum depth, or once the path's throughput
/// falls below <see cref="Viewing.ViewPlane.MinimumThroughput"/>, a ray carries nothing.
/// </summary>
public abstract class Tracer
{
    protected Tracer(World world)
    {
        World = world;
    }

    public World World { get; }

    /// <summary>Traces a primary ray (throughput 1).</summary>
    public RGBColor TraceRay(in Ray ray, int depth) => TraceRay(ray, depth, 1.0, out _);

    /// <summary>
    /// Traces a ray spawned at <paramref name="parent"/>'s hit whose radiance the caller scales by
    /// <paramref name="scale"/>: one level deeper, with the path throughput multiplied by the scale's largest channel.
    /// </summary>
    public RGBColor TraceSpawned(ShadingRecord parent, in Ray ray, RGBColor scale) => TraceSpawned(parent, ray, scale, out _);

    /// <inheritdoc cref="TraceSpawned(ShadingRecord, in Ray, RGBColor)"/>
    public RGBColor TraceSpawned(ShadingRecord parent, in Ray ray, RGBColor scale, out double tmin) =>
        TraceRay(ray, parent.Depth + 1, parent.Weight * scale.MaxComponent, out tmin);

    /// <summary>
    /// Traces a ray whose path has throughput <paramref name="weight"/>; also returns the distance to the hit
    /// (<see cref="MathConstants.HugeValue"/> on a miss or when the ray is not traced), for Beer's law.
    /// </summary>
    public RGBColor TraceRay(in Ray ray, int depth, double weight, out double tmin)
    {
        tmin = MathConstants.HugeValue;
        // Dielectrics split every ray in two, so without the throughput test the ray tree grows as 2^depth.
        if (depth > World.ViewPlane.MaxDepth || !(weight >= World.ViewPlane.MinimumThroughput))
            return RGBColor.Black;
        var sr = ShadingRecordPool.Rent();
        try
        {
            if (!World.HitObjects(ray, sr) || sr.Material is null)
                return World.BackgroundRadiance(ray);
            sr.Depth = depth;
            sr.Weight = weight;
            tmin = sr.T;
            return Shade(sr.Material, sr);
        }
        finally
        {
            ShadingRecordPool.Return();
        }
    }

    protected abstract RGBColor Shade(Material material, ShadingRecord sr);
}
