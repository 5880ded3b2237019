using RayTracer.Colors;
using RayTracer.Geometry;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Sampling;
using RayTracer.Tracing;

namespace RayTracer.Lights;

/// <summary>
/// Light emitted by a surface (rectangle, disk, sphere, …) with an emissive material. Each direction query
/// samples a point on the surface uniformly by area; the estimator divides by its density.
/// </summary>
public sealed class AreaLight : Light
{
    private sealed class LightSample
    {
        public Point3D Point;
        public Normal3D Normal;
        public Vector3D Wi;
    }

    private readonly ThreadLocal<LightSample> _sample = new(() => new LightSample());

    /// <param name="sampler">Optional stratified sampler for points on the shape; without one, the calling
    /// thread's <see cref="SeededRandom.Current"/> supplies them.</param>
    public AreaLight(ISampledShape shape, Material emitter, Sampler? sampler = null)
    {
        Shape = shape;
        Emitter = emitter;
        Sampler = sampler;
    }

    public ISampledShape Shape { get; }
    public Material Emitter { get; }
    public Sampler? Sampler { get; }

    private Point2D NextUnitSquareSample()
    {
        if (Sampler is { } sampler)
            return sampler.SampleUnitSquare();
        var random = SeededRandom.Current;
        return new Point2D(random.NextDouble(), random.NextDouble());
    }

    public override Vector3D GetDirection(ShadingRecord sr)
    {
        var s = _sample.Value!;
        s.Point = Shape.Sample(NextUnitSquareSample());
        s.Normal = Shape.GetNormal(s.Point);
        s.Wi = (s.Point - sr.HitPoint).Normalized();
        sr.Direction = s.Wi;
        return s.Wi;
    }

    /// <summary>The distance to the sampled point, shortened a little so the light's own surface does not shadow itself.</summary>
    public override double ShadowDistance(in Ray ray)
    {
        var s = _sample.Value!;
        var distance = (s.Point - ray.o).Dot(ray.d);
        return distance * (1 - Tolerances.ShadowRayShortening);
    }

    public override RGBColor L(ShadingRecord sr)
    {
        var s = _sample.Value!;
        return -s.Normal.Dot(s.Wi) > 0 ? Emitter.GetLe(sr) : RGBColor.Black;
    }

    public override double G(ShadingRecord sr)
    {
        var s = _sample.Value!;
        var cos = -s.Normal.Dot(s.Wi);
        return cos / s.Point.DistanceSquared(sr.HitPoint);
    }

    public override double Pdf(ShadingRecord sr) => Shape.Pdf(sr);
}
