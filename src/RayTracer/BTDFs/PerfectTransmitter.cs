using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.BTDFs;

/// <summary>Specular transmission with a fixed fraction kt and index of refraction <see cref="Ior"/>.</summary>
public sealed class PerfectTransmitter : BTDF
{
    public PerfectTransmitter(double kt = 0.9, double ior = 1.5)
    {
        Kt = kt;
        Ior = ior;
    }

    public double Kt { get; set; }
    public double Ior { get; set; }

    public override bool TotalInternalReflection(ShadingRecord sr) =>
        !Refract(-sr.Ray.d.Normalized(), sr.Normal, Ior, out _, out _);

    /// <summary>Radiance is divided by η² on crossing the interface; divided by |n·wt| so the caller's cosine cancels.</summary>
    public override RGBColor SampleF(ShadingRecord sr, Vector3D wo, out Vector3D wt)
    {
        if (!Refract(wo, sr.Normal, Ior, out wt, out var cosT))
            return RGBColor.Black;
        var eta = sr.Normal.Dot(wo) < 0 ? 1.0 / Ior : Ior;
        return new RGBColor(Kt / (eta * eta) / cosT);
    }
}
