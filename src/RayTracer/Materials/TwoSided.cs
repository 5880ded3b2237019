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

    public override RGBColor Shade(ShadingRecord sr) => Inner.Shade(FaceViewer(sr));

    public override RGBColor AreaLightShade(ShadingRecord sr) => Inner.AreaLightShade(FaceViewer(sr));

    public override RGBColor PathShade(ShadingRecord sr) => Inner.PathShade(FaceViewer(sr));

    public override RGBColor GlobalShade(ShadingRecord sr) => Inner.GlobalShade(FaceViewer(sr));

    private static ShadingRecord FaceViewer(ShadingRecord sr)
    {
        if (sr.Normal.Dot(sr.Ray.d) > 0)
            sr.Normal = -sr.Normal;
        return sr;
    }
}
