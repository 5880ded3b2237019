using RayTracer.BRDFs;
using RayTracer.BTDFs;
using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Materials;

/// <summary>
/// Mirror reflection and refraction in fixed fractions (simple glass). On total internal reflection all the
/// light is reflected, whatever the reflection fraction.
/// </summary>
public sealed class SplitScattering(PerfectSpecular reflection, PerfectTransmitter transmission) : SpecularScattering
{
    public PerfectSpecular Reflection { get; } = reflection;
    public PerfectTransmitter Transmission { get; } = transmission;

    public override bool Transmits => true;

    public override int Sample(ShadingRecord sr, Vector3D wo, Span<BsdfSample> samples)
    {
        var fr = Reflection.SampleF(sr, wo, out var wi, out _);
        if (Transmission.TotalInternalReflection(sr))
        {
            samples[0] = new BsdfSample(wi, RGBColor.White, 1.0, 1.0);
            return 1;
        }
        var ft = Transmission.SampleF(sr, wo, out var wt);
        samples[0] = new BsdfSample(wi, fr, Math.Abs(sr.Normal.Dot(wi)), 1.0);
        samples[1] = new BsdfSample(wt, ft, Math.Abs(sr.Normal.Dot(wt)), 1.0);
        return 2;
    }
}
