using RayTracer.BRDFs;
using RayTracer.BTDFs;
using RayTracer.Colors;
using RayTracer.Tracing;

namespace RayTracer.Materials;

/// <summary>Phong surface with fixed-fraction mirror reflection and refraction (simple glass).</summary>
public sealed class Transparent : Phong
{
    public Transparent(double ka = 0.0, double kd = 0.0, RGBColor? cd = null, double ks = 0.2, double exponent = 2000,
        double kr = 0.1, double kt = 0.9, double ior = 1.5)
        : base(ka, kd, cd, ks, exponent)
    {
        ReflectiveBrdf = new PerfectSpecular(kr);
        SpecularBtdf = new PerfectTransmitter(kt, ior);
    }

    public PerfectSpecular ReflectiveBrdf { get; }
    public PerfectTransmitter SpecularBtdf { get; }

    private RGBColor ReflectAndRefract(ShadingRecord sr)
    {
        var tracer = sr.World!.Tracer!;
        var wo = -sr.Ray.d.Normalized();
        var fr = ReflectiveBrdf.SampleF(sr, wo, out var wi, out _);
        var reflected = sr.SpawnRay(wi);
        if (SpecularBtdf.TotalInternalReflection(sr))
            return tracer.TraceSpawned(sr, reflected, RGBColor.White); // all light is reflected
        var ft = SpecularBtdf.SampleF(sr, wo, out var wt);
        var cosI = Math.Abs(sr.Normal.Dot(wi));
        var cosT = Math.Abs(sr.Normal.Dot(wt));
        return fr * tracer.TraceSpawned(sr, reflected, fr * cosI) * cosI
            + ft * tracer.TraceSpawned(sr, sr.SpawnRay(wt), ft * cosT) * cosT;
    }

    public override RGBColor Shade(ShadingRecord sr) => base.Shade(sr) + ReflectAndRefract(sr);

    public override RGBColor AreaLightShade(ShadingRecord sr) => base.AreaLightShade(sr) + ReflectAndRefract(sr);

    public override RGBColor PathShade(ShadingRecord sr) => ReflectAndRefract(sr);

    public override RGBColor GlobalShade(ShadingRecord sr) => ReflectAndRefract(sr);
}
