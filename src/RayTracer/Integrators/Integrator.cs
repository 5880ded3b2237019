using RayTracer.Colors;
using RayTracer.Lights;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Scenes;
using RayTracer.Tracing;
using RayTracer.Viewing;

namespace RayTracer.Integrators;

/// <summary>
/// A light transport algorithm: it alone traces rays and casts shadow rays. It finds the nearest hit, asks
/// the material for its BSDF and emission and the lights for their radiance and samples, and combines them
/// into the radiance carried back along the ray. Beyond the view plane's maximum depth, or once the path's
/// throughput falls below <see cref="ViewPlane.MinimumThroughput"/>, a ray carries nothing.
/// </summary>
public abstract class Integrator
{
    protected Integrator(World world)
    {
        World = world;
    }

    public World World { get; }

    /// <summary>
    /// Average radiance over the pixel at (<paramref name="column"/>, <paramref name="row"/>) of
    /// <paramref name="camera"/>'s image, row 0 at the top: one primary ray per view-plane sample.
    /// </summary>
    public RGBColor RenderPixel(Camera camera, int column, int row)
    {
        var vp = World.ViewPlane;
        if (camera.EyeFor(vp, column, out var eyeColumn) is not { } eye)
            return RGBColor.Black;
        var radiance = SamplePixel(eye, vp, eyeColumn, row);
        // A camera made of eye cameras (a stereo pair) adds its own exposure to theirs.
        return ReferenceEquals(eye, camera) ? radiance : radiance * camera.Exposure;
    }

    private RGBColor SamplePixel(Camera camera, ViewPlane vp, int column, int row)
    {
        var r = vp.VerticalResolution - 1 - row;
        var s = vp.PixelSize;
        var sum = RGBColor.Black;
        var n = vp.NumSamples;
        for (var j = 0; j < n; j++)
        {
            var sp = vp.Sampler.SampleUnitSquare();
            var pp = new Point2D(
                s * (column - 0.5 * vp.HorizontalResolution + sp.x),
                s * (r - 0.5 * vp.VerticalResolution + sp.y));
            if (camera.GetRay(pp, vp, out var ray))
            {
                ray.tMin = World.RayEpsilon;
                RayStatistics.CountPrimary();
                sum += TraceRay(ray, 0);
            }
        }
        return sum * (camera.Exposure / n);
    }

    /// <summary>Traces a primary ray (throughput 1).</summary>
    public RGBColor TraceRay(in Ray ray, int depth) => TraceRay(ray, depth, 1.0, out _);

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
            return Li(sr.Material, sr);
        }
        finally
        {
            ShadingRecordPool.Return();
        }
    }

    /// <summary>Radiance leaving the hit in <paramref name="sr"/> back along its ray.</summary>
    protected abstract RGBColor Li(Material material, ShadingRecord sr);

    /// <summary>Unit direction from the hit back towards the ray's origin.</summary>
    protected static Vector3D Outgoing(ShadingRecord sr) => -sr.Ray.d.Normalized();

    /// <summary>The world's ambient light times the material's ambient reflectance (black without ambient light).</summary>
    protected RGBColor Ambient(Material material, ShadingRecord sr)
    {
        if (World.AmbientLight is not { } ambient)
            return RGBColor.Black;
        var rho = material.AmbientReflectance(sr);
        return rho * AmbientRadiance(ambient, sr);
    }

    private RGBColor AmbientRadiance(Light ambient, ShadingRecord sr)
    {
        if (!ambient.SamplesVisibility)
            return ambient.L(sr);
        var shadowRay = sr.SpawnRay(ambient.GetDirection(sr));
        return ambient.CastsShadows && World.ShadowHit(shadowRay, ambient.ShadowDistance(shadowRay))
            ? ambient.ShadowedL(sr)
            : ambient.L(sr);
    }

    /// <summary>
    /// Σ over lights of f(wo, wi)·L·(n·wi) [·G / pdf when <paramref name="sampledLights"/>], with a shadow ray
    /// towards each light that casts shadows. Lights behind the surface contribute nothing.
    /// </summary>
    protected RGBColor DirectLighting(ShadingRecord sr, in Bsdf bsdf, Vector3D wo, bool sampledLights)
    {
        var sum = RGBColor.Black;
        var lights = World.Lights;
        for (var i = 0; i < lights.Count; i++)
        {
            var light = lights[i];
            var wi = light.GetDirection(sr);
            var ndotwi = sr.Normal.Dot(wi);
            if (ndotwi <= 0)
                continue;
            if (light.CastsShadows)
            {
                var shadowRay = sr.SpawnRay(wi);
                if (World.ShadowHit(shadowRay, light.ShadowDistance(shadowRay)))
                    continue;
            }
            var term = bsdf.F(wo, wi) * light.L(sr) * ndotwi;
            if (sampledLights)
            {
                var pdf = light.Pdf(sr);
                if (pdf <= 0)
                    continue;
                term = term * (light.G(sr) / pdf);
            }
            sum += term;
        }
        return sum;
    }

    /// <summary>Ambient plus direct light reflected at the hit: what a surface shows without tracing further.</summary>
    protected RGBColor Reflected(Material material, ShadingRecord sr, in Bsdf bsdf, Vector3D wo, bool sampledLights) =>
        Ambient(material, sr) + DirectLighting(sr, bsdf, wo, sampledLights);

    /// <summary>Σ f·Li·(cos / pdf) over <paramref name="samples"/>, each Li traced one level deeper.</summary>
    protected RGBColor Scatter(ShadingRecord sr, ReadOnlySpan<BsdfSample> samples)
    {
        var sum = RGBColor.Black;
        foreach (var s in samples)
        {
            var weight = s.Weight;
            var li = TraceRay(sr.SpawnRay(s.Wi), sr.Depth + 1, sr.Weight * (s.F * weight).MaxComponent, out var t);
            // Beer's attenuation depends on the hit distance, so only f enters the throughput above.
            var f = s.Absorbs ? Dielectric.Attenuation(s.Filter, t) * s.F : s.F;
            sum += f * li * weight;
        }
        return sum;
    }

    /// <summary>Radiance brought back by the specular lobes' rays.</summary>
    protected RGBColor TraceSpecular(ShadingRecord sr, in Bsdf bsdf, Vector3D wo)
    {
        Span<BsdfSample> samples = stackalloc BsdfSample[SpecularScattering.MaxSamples];
        return Scatter(sr, samples[..bsdf.SampleSpecular(wo, samples)]);
    }

    /// <summary>Radiance brought back by one path bounce (the specular lobes, or else one diffuse direction).</summary>
    protected RGBColor TraceBounce(ShadingRecord sr, in Bsdf bsdf, Vector3D wo)
    {
        Span<BsdfSample> samples = stackalloc BsdfSample[SpecularScattering.MaxSamples];
        return Scatter(sr, samples[..bsdf.SampleBounce(wo, samples)]);
    }
}
