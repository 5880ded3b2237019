using RayTracer.Colors;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.Materials;

/// <summary>
/// A light-emitting surface: radiance ls·ce from its front side (the side the normal points to),
/// black from behind. The colour may come from a texture. It scatters nothing.
/// </summary>
public class Emissive : Material
{
    public Emissive(double radianceScale = 1.0, RGBColor? color = null)
        : this(radianceScale, new ConstantTexture<RGBColor>(color ?? RGBColor.White))
    {
    }

    public Emissive(double radianceScale, Texture<RGBColor> color)
    {
        RadianceScale = radianceScale;
        Color = color;
    }

    public double RadianceScale { get; set; }
    public Texture<RGBColor> Color { get; set; }

    /// <summary>When false, the back side emits too (for environment domes seen from inside).</summary>
    public bool OneSided { get; set; } = true;

    public override RGBColor GetLe(ShadingRecord sr) => RadianceScale * Color.GetValue(sr);

    public override RGBColor Emitted(ShadingRecord sr) =>
        !OneSided || -sr.Normal.Dot(sr.Ray.d) > 0 ? GetLe(sr) : RGBColor.Black;
}
