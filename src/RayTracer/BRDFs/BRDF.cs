using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.BRDFs;

/// <summary>
/// Bidirectional reflectance distribution function. <c>wo</c> points to the viewer, <c>wi</c> to the light,
/// both away from the surface and unit length.
/// </summary>
public abstract class BRDF
{
    /// <summary>Value of the BRDF for a pair of directions (black for delta distributions).</summary>
    public virtual RGBColor F(ShadingRecord sr, Vector3D wo, Vector3D wi) => RGBColor.Black;

    /// <summary>Samples an incident direction; returns f and the density of <paramref name="wi"/> (solid angle).</summary>
    public virtual RGBColor SampleF(ShadingRecord sr, Vector3D wo, out Vector3D wi, out double pdf)
    {
        wi = default;
        pdf = 0;
        return RGBColor.Black;
    }

    /// <summary>Density (solid angle) with which <see cref="SampleF"/> draws <paramref name="wi"/>; 0 for delta distributions.</summary>
    public virtual double Pdf(ShadingRecord sr, Vector3D wo, Vector3D wi) => 0.0;

    /// <summary>Hemispherical-directional reflectance (the fraction of uniform incident light reflected).</summary>
    public virtual RGBColor Rho(ShadingRecord sr, Vector3D wo) => RGBColor.Black;
}
