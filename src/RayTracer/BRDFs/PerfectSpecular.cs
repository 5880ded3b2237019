using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.BRDFs;

/// <summary>Mirror reflection of strength kr·cr; a delta distribution, so it is only sampled.</summary>
public sealed class PerfectSpecular : BRDF
{
    public PerfectSpecular(double kr = 0.75, RGBColor? cr = null)
    {
        Kr = kr;
        Color = new ConstantTexture<RGBColor>(cr ?? RGBColor.White);
    }

    public double Kr { get; set; }
    public Texture<RGBColor> Color { get; set; }

    public static Vector3D Reflect(Vector3D wo, Normal3D n) => -wo + 2.0 * n.Dot(wo) * n.ToVector();

    /// <summary>Returns kr·cr / |n·wi| so that f·|n·wi| / pdf with pdf = 1 gives kr·cr.</summary>
    public override RGBColor SampleF(ShadingRecord sr, Vector3D wo, out Vector3D wi, out double pdf)
    {
        wi = Reflect(wo, sr.Normal);
        pdf = 1;
        return Kr * Color.GetValue(sr) / Math.Abs(sr.Normal.Dot(wi));
    }

    public override RGBColor Rho(ShadingRecord sr, Vector3D wo) => Kr * Color.GetValue(sr);
}
