using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Lights;

/// <summary>
/// A light source as seen from a shading point: where light comes from, how much, and with what density.
/// For area lights <see cref="GetDirection"/> draws a sample point, and the following calls
/// (<see cref="ShadowDistance"/>, <see cref="L"/>, <see cref="G"/>, <see cref="Pdf"/>) on the same thread
/// refer to that sample. Lights trace nothing: the integrator casts the shadow ray.
/// </summary>
public abstract class Light
{
    public bool CastsShadows { get; set; } = true;

    /// <summary>Unit direction from the hit point towards the light.</summary>
    public abstract Vector3D GetDirection(ShadingRecord sr);

    /// <summary>Incident radiance at the hit point.</summary>
    public abstract RGBColor L(ShadingRecord sr);

    /// <summary>
    /// How far along <paramref name="ray"/> (from the hit point towards the light, unit direction) an
    /// object must lie to block the light: occluders at or beyond it are behind the light.
    /// </summary>
    public virtual double ShadowDistance(in Ray ray) => MathConstants.HugeValue;

    /// <summary>
    /// True for an ambient light dimmed where the hemisphere above the point is blocked: the integrator casts
    /// one shadow ray along <see cref="GetDirection"/> and uses <see cref="ShadowedL"/> when it is blocked.
    /// </summary>
    public virtual bool SamplesVisibility => false;

    /// <summary>Radiance still received when the light's shadow ray is blocked (see <see cref="SamplesVisibility"/>).</summary>
    public virtual RGBColor ShadowedL(ShadingRecord sr) => RGBColor.Black;

    /// <summary>Geometric factor cos θ' / d² of area lights; 1 for the others.</summary>
    public virtual double G(ShadingRecord sr) => 1.0;

    /// <summary>Density of the sampled direction or point; 1 for delta lights.</summary>
    public virtual double Pdf(ShadingRecord sr) => 1.0;
}
