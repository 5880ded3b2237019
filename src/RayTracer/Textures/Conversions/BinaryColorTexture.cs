using RayTracer.Colors;
using RayTracer.Tracing;

namespace RayTracer.Textures.Conversions;

/// <summary>Colours a binary texture: <see cref="OnColor"/> where it is true, <see cref="OffColor"/> elsewhere.</summary>
public sealed class BinaryColorTexture(Texture<bool> pattern, RGBColor onColor, RGBColor offColor) : Texture<RGBColor>
{
    public Texture<bool> Pattern { get; } = pattern;
    public RGBColor OnColor { get; set; } = onColor;
    public RGBColor OffColor { get; set; } = offColor;

    public override RGBColor GetValue(ShadingRecord sr) => Pattern.GetValue(sr) ? OnColor : OffColor;
}
