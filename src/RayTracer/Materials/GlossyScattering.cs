using RayTracer.BRDFs;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Materials;

/// <summary>One ray drawn from a Phong lobe around the mirror direction (blurred reflection).</summary>
public sealed class GlossyScattering(GlossySpecular brdf) : SpecularScattering
{
    public GlossySpecular Brdf { get; } = brdf;

    public override int Sample(ShadingRecord sr, Vector3D wo, Span<BsdfSample> samples)
    {
        var fr = Brdf.SampleF(sr, wo, out var wi, out var pdf);
        if (pdf <= 0)
            return 0;
        samples[0] = new BsdfSample(wi, fr, sr.Normal.Dot(wi), pdf);
        return 1;
    }
}
