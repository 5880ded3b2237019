using RayTracer.Util;

namespace RayTracer.Lights;

/// <summary>A light source as seen from a shading point.</summary>
public abstract class Light
{
    public bool CastsShadows { get; set; } = true;

    /// <summary>Unit direction from the hit point towards the light.</summary>
    public abstract Vector3D GetDirection(ShadingRecord sr);

    /// <summary>Incident radiance at the hit point.</summary>
    public abstract RGBColor L(ShadingRecord sr);

    public abstract bool InShadow(in Ray ray, ShadingRecord sr);

    /// <summary>Geometric factor of area lights.</summary>
    public abstract double G(ShadingRecord sr);

    public abstract double Pdf(ShadingRecord sr);
}
