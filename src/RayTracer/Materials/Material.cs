using RayTracer.Colors;
using RayTracer.Tracing;

namespace RayTracer.Materials;

/// <summary>
/// What a surface does with light, without tracing anything: the BSDF it scatters with at a hit, the radiance
/// it emits, and the reflectance of its ambient term. Integrators (<see cref="Integrators.Integrator"/>) trace
/// the rays and meet the lights.
/// </summary>
public abstract class Material
{
    /// <summary>The scattering lobes at the hit (<see cref="Bsdf.None"/> for a surface that only emits).</summary>
    public virtual Bsdf GetBsdf(ShadingRecord sr) => Bsdf.None;

    /// <summary>Radiance emitted at the hit back along the ray (black for surfaces that do not emit).</summary>
    public virtual RGBColor Emitted(ShadingRecord sr) => RGBColor.Black;

    /// <summary>Emitted radiance regardless of the side it is seen from (non-black only for emissive materials).</summary>
    public virtual RGBColor GetLe(ShadingRecord sr) => RGBColor.Black;

    /// <summary>Fraction of the world's ambient light the surface reflects.</summary>
    public virtual RGBColor AmbientReflectance(ShadingRecord sr) => RGBColor.Black;
}
