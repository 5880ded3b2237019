using RayTracer.Colors;
using RayTracer.Tracing;

namespace RayTracer.Materials;

/// <summary>
/// Shades both faces of a surface alike by turning the normal towards the incoming ray first. Meshes
/// from files are often wound inconsistently; without this their back faces would show only ambient light.
/// </summary>
public sealed class TwoSided(Material inner) : Material
{
    public Material Inner { get; } = inner;

    public override Bsdf GetBsdf(ShadingRecord sr) => Inner.GetBsdf(FaceViewer(sr));

    public override RGBColor Emitted(ShadingRecord sr) => Inner.Emitted(FaceViewer(sr));

    public override RGBColor GetLe(ShadingRecord sr) => Inner.GetLe(sr);

    public override RGBColor AmbientReflectance(ShadingRecord sr) => Inner.AmbientReflectance(FaceViewer(sr));

    private static ShadingRecord FaceViewer(ShadingRecord sr)
    {
        if (sr.Normal.Dot(sr.Ray.d) > 0)
            sr.Normal = -sr.Normal;
        return sr;
    }
}
