using RayTracer.BRDFs;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Materials;

/// <summary>One ray in the mirror direction, weighted by the mirror's reflectance.</summary>
public sealed class MirrorScattering(PerfectSpecular brdf) : SpecularScattering
{
    public PerfectSpecular Brdf { get; } = brdf;

    public override int Sample(ShadingRecord sr, Vector3D wo, Span<BsdfSample> samples)
    {
        var fr = Brdf.SampleF(sr, wo, out var wi, out _);
        samples[0] = new BsdfSample(wi, fr, Math.Abs(sr.Normal.Dot(wi)), 1.0);
        return 1;
    }
}
