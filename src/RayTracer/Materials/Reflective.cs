using RayTracer.BRDFs;
using RayTracer.Colors;
using RayTracer.Tracing;

namespace RayTracer.Materials;

/// <summary>Phong plus a perfect mirror term traced recursively.</summary>
public class Reflective : Phong
{
    public Reflective(double ka = 0.25, double kd = 0.5, RGBColor? cd = null, double ks = 0.15, double exponent = 100,
        double kr = 0.75, RGBColor? cr = null)
        : base(ka, kd, cd, ks, exponent)
    {
        ReflectiveBrdf = new PerfectSpecular(kr, cr);
    }

    public PerfectSpecular ReflectiveBrdf { get; }

    private RGBColor Mirror(ShadingRecord sr)
    {
        var wo = -sr.Ray.d.Normalized();
        var fr = ReflectiveBrdf.SampleF(sr, wo, out var wi, out _);
        var cos = Math.Abs(sr.Normal.Dot(wi));
        return fr * sr.World!.Tracer!.TraceSpawned(sr, sr.SpawnRay(wi), fr * cos) * cos;
    }

    public override RGBColor Shade(ShadingRecord sr) => base.Shade(sr) + Mirror(sr);

    public override RGBColor AreaLightShade(ShadingRecord sr) => base.AreaLightShade(sr) + Mirror(sr);

    public override RGBColor PathShade(ShadingRecord sr) => Mirror(sr);

    public override RGBColor GlobalShade(ShadingRecord sr) =>
        sr.Depth == 0 ? base.AreaLightShade(sr) + Mirror(sr) : Mirror(sr);
}
