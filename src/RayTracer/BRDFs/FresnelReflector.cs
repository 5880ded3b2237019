using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.BRDFs;

/// <summary>Mirror reflection weighted by the unpolarised Fresnel reflectance of a dielectric interface.</summary>
public sealed class FresnelReflector : BRDF
{
    public FresnelReflector(double etaIn = 1.5, double etaOut = 1.0)
    {
        EtaIn = etaIn;
        EtaOut = etaOut;
    }

    /// <summary>Refractive index inside the object (the side the normal points away from).</summary>
    public double EtaIn { get; set; }

    /// <summary>Refractive index outside the object.</summary>
    public double EtaOut { get; set; }

    /// <summary>
    /// Fresnel reflectance seen from direction <paramref name="wo"/> (pointing away from the surface),
    /// with the normal <paramref name="n"/> pointing outwards. Returns 1 on total internal reflection.
    /// </summary>
    public static double Reflectance(Vector3D wo, Normal3D n, double etaIn, double etaOut)
    {
        var cosI = n.Dot(wo);
        var eta = etaIn / etaOut;
        if (cosI < 0)
        {
            cosI = -cosI;
            eta = 1.0 / eta; // the ray is inside the object
        }
        var cosT2 = 1.0 - (1.0 - cosI * cosI) / (eta * eta);
        if (cosT2 < 0)
            return 1.0;
        var cosT = Math.Sqrt(cosT2);
        var rParallel = (eta * cosI - cosT) / (eta * cosI + cosT);
        var rPerpendicular = (cosI - eta * cosT) / (cosI + eta * cosT);
        return 0.5 * (rParallel * rParallel + rPerpendicular * rPerpendicular);
    }

    public override RGBColor SampleF(ShadingRecord sr, Vector3D wo, out Vector3D wi, out double pdf)
    {
        wi = PerfectSpecular.Reflect(wo, sr.Normal);
        pdf = 1;
        var kr = Reflectance(wo, sr.Normal, EtaIn, EtaOut);
        return new RGBColor(kr / Math.Abs(sr.Normal.Dot(wi)));
    }
}
