using RayTracer.BRDFs;
using RayTracer.BTDFs;
using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Materials;

/// <summary>
/// A dielectric interface: reflection and refraction weighted by the Fresnel equations, each ray filtered by
/// the medium it travels through (inside or outside the object).
/// </summary>
public sealed class FresnelScattering(FresnelReflector reflection, FresnelTransmitter transmission) : SpecularScattering
{
    public FresnelReflector Reflection { get; } = reflection;
    public FresnelTransmitter Transmission { get; } = transmission;

    /// <summary>Fraction of each channel surviving one unit of distance inside the object.</summary>
    public RGBColor FilterInside { get; set; } = RGBColor.White;

    public RGBColor FilterOutside { get; set; } = RGBColor.White;

    public override bool Transmits => true;

    public override int Sample(ShadingRecord sr, Vector3D wo, Span<BsdfSample> samples)
    {
        var fr = Reflection.SampleF(sr, wo, out var wi, out _);
        var ndotwi = sr.Normal.Dot(wi);
        // The reflected ray stays on the side it came from: inside if n·wi < 0.
        var reflectedFilter = ndotwi < 0 ? FilterInside : FilterOutside;
        if (Transmission.TotalInternalReflection(sr))
        {
            samples[0] = new BsdfSample(wi, RGBColor.White, 1.0, 1.0) { Absorbs = true, Filter = reflectedFilter };
            return 1;
        }
        var ft = Transmission.SampleF(sr, wo, out var wt);
        var transmittedFilter = ndotwi < 0 ? FilterOutside : FilterInside;
        samples[0] = new BsdfSample(wi, fr, Math.Abs(ndotwi), 1.0) { Absorbs = true, Filter = reflectedFilter };
        samples[1] = new BsdfSample(wt, ft, Math.Abs(sr.Normal.Dot(wt)), 1.0) { Absorbs = true, Filter = transmittedFilter };
        return 2;
    }
}
