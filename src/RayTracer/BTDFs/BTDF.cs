using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.BTDFs;

/// <summary>Bidirectional transmittance distribution function (light passing through a surface).</summary>
public abstract class BTDF
{
    public virtual RGBColor F(ShadingRecord sr, Vector3D wo, Vector3D wi) => RGBColor.Black;

    /// <summary>Samples the transmitted direction <paramref name="wt"/>.</summary>
    public abstract RGBColor SampleF(ShadingRecord sr, Vector3D wo, out Vector3D wt);

    public virtual RGBColor Rho(ShadingRecord sr, Vector3D wo) => RGBColor.Black;

    /// <summary>True when light arriving along wo is totally internally reflected.</summary>
    public abstract bool TotalInternalReflection(ShadingRecord sr);

    /// <summary>
    /// Snell refraction of the viewing direction <paramref name="wo"/> through a surface with outward normal
    /// <paramref name="n"/> and relative index eta = n_inside / n_outside. False on total internal reflection.
    /// </summary>
    public static bool Refract(Vector3D wo, Normal3D n, double eta, out Vector3D wt, out double cosT)
    {
        var normal = n.ToVector();
        var cosI = normal.Dot(wo);
        if (cosI < 0)
        {
            cosI = -cosI;
            normal = -normal;
            eta = 1.0 / eta;
        }
        var cosT2 = 1.0 - (1.0 - cosI * cosI) / (eta * eta);
        if (cosT2 < 0)
        {
            wt = default;
            cosT = 0;
            return false;
        }
        cosT = Math.Sqrt(cosT2);
        wt = -wo / eta - (cosT - cosI / eta) * normal;
        return true;
    }
}
