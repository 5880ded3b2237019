using RayTracer.BRDFs;
using RayTracer.BTDFs;
using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Materials;

/// <summary>
/// Glass-like dielectric: Fresnel-weighted reflection and refraction, with Beer's-law colour filtering of
/// the light travelling inside (filter^distance) and outside (usually white) the object.
/// </summary>
public sealed class Dielectric : Phong
{
    public Dielectric(double etaIn = 1.5, double etaOut = 1.0, RGBColor? filterInside = null, RGBColor? filterOutside = null,
        double ks = 0.2, double exponent = 2000)
        : base(0.0, 0.0, RGBColor.White, ks, exponent)
    {
        FresnelBrdf = new FresnelReflector(etaIn, etaOut);
        FresnelBtdf = new FresnelTransmitter(etaIn, etaOut);
        FilterInside = filterInside ?? RGBColor.White;
        FilterOutside = filterOutside ?? RGBColor.White;
    }

    public FresnelReflector FresnelBrdf { get; }
    public FresnelTransmitter FresnelBtdf { get; }

    /// <summary>Fraction of each channel surviving one unit of distance inside the object.</summary>
    public RGBColor FilterInside { get; set; }

    public RGBColor FilterOutside { get; set; }

    /// <summary>Beer's law: a colour filter applied over a distance.</summary>
    public static RGBColor Attenuation(RGBColor filter, double distance) =>
        distance >= MathConstants.HugeValue ? RGBColor.White : filter.Pow(distance);

    private RGBColor ReflectAndRefract(ShadingRecord sr)
    {
        var tracer = sr.World!.Tracer!;
        var wo = -sr.Ray.d.Normalized();
        var fr = FresnelBrdf.SampleF(sr, wo, out var wi, out _);
        var reflected = sr.SpawnRay(wi);
        var ndotwi = sr.Normal.Dot(wi);
        // The reflected ray stays on the side it came from: inside if n·wi < 0.
        var reflectedFilter = ndotwi < 0 ? FilterInside : FilterOutside;

        if (FresnelBtdf.TotalInternalReflection(sr))
        {
            var lr = tracer.TraceSpawned(sr, reflected, RGBColor.White, out var t);
            return Attenuation(reflectedFilter, t) * lr;
        }

        var ft = FresnelBtdf.SampleF(sr, wo, out var wt);
        var transmittedFilter = ndotwi < 0 ? FilterOutside : FilterInside;
        var cosI = Math.Abs(ndotwi);
        var cosT = Math.Abs(sr.Normal.Dot(wt));
        // Beer's attenuation depends on the hit distance, so only the Fresnel factors enter the throughput.
        var lrr = tracer.TraceSpawned(sr, reflected, fr * cosI, out var tr);
        var ltt = tracer.TraceSpawned(sr, sr.SpawnRay(wt), ft * cosT, out var tt);
        return Attenuation(reflectedFilter, tr) * fr * lrr * cosI
            + Attenuation(transmittedFilter, tt) * ft * ltt * cosT;
    }

    public override RGBColor Shade(ShadingRecord sr) => base.Shade(sr) + ReflectAndRefract(sr);

    public override RGBColor AreaLightShade(ShadingRecord sr) => base.AreaLightShade(sr) + ReflectAndRefract(sr);

    public override RGBColor PathShade(ShadingRecord sr) => ReflectAndRefract(sr);

    public override RGBColor GlobalShade(ShadingRecord sr) => ReflectAndRefract(sr);
}
