using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Lights;

/// <summary>
/// A light source as seen from a shading point. For area lights <see cref="GetDirection"/> draws a sample
/// point, and the following calls (<see cref="InShadow"/>, <see cref="L"/>, <see cref="G"/>, <see cref="Pdf"/>)
/// on the same thread refer to that sample.
/// </summary>
public abstract class Light
{
    public bool CastsShadows { get; set; } = true;

    /// <summary>Unit direction from the hit point towards the light.</summary>
    public abstract Vector3D GetDirection(ShadingRecord sr);

    /// <summary>Incident radiance at the hit point.</summary>
    public abstract RGBColor L(ShadingRecord sr);

    /// <summary>True if something blocks <paramref name="ray"/> (from the hit point towards the light).</summary>
    public abstract bool InShadow(in Ray ray, ShadingRecord sr);

    /// <summary>Geometric factor cos θ' / d² of area lights; 1 for the others.</summary>
    public virtual double G(ShadingRecord sr) => 1.0;

    /// <summary>Density of the sampled direction or point; 1 for delta lights.</summary>
    public virtual double Pdf(ShadingRecord sr) => 1.0;
}
