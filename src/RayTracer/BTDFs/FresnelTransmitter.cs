using RayTracer.BRDFs;
using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.BTDFs;

/// <summary>Specular transmission weighted by 1 − Fresnel reflectance, so energy splits exactly with <see cref="FresnelReflector"/>.</summary>
public sealed class FresnelTransmitter : BTDF
{
    public FresnelTransmitter(double etaIn = 1.5, double etaOut = 1.0)
    {
        EtaIn = etaIn;
        EtaOut = etaOut;
    }

    public double EtaIn { get; set; }
    public double EtaOut { get; set; }

    public override bool TotalInternalReflection(ShadingRecord sr) =>
        !Refract(-sr.Ray.d.Normalized(), sr.Normal, EtaIn / EtaOut, out _, out _);

    public override RGBColor SampleF(ShadingRecord sr, Vector3D wo, out Vector3D wt)
    {
        if (!Refract(wo, sr.Normal, EtaIn / EtaOut, out wt, out var cosT))
            return RGBColor.Black;
        var kt = 1.0 - FresnelReflector.Reflectance(wo, sr.Normal, EtaIn, EtaOut);
        var eta = sr.Normal.Dot(wo) < 0 ? EtaOut / EtaIn : EtaIn / EtaOut;
        return new RGBColor(kt / (eta * eta) / cosT);
    }
}
