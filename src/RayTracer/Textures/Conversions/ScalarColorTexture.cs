using RayTracer.Colors;
using RayTracer.Tracing;

namespace RayTracer.Textures.Conversions;

/// <summary>Blends two colours by a scalar texture clamped to [0, 1] (noise → colour).</summary>
public sealed class ScalarColorTexture(Texture<double> scalar, RGBColor low, RGBColor high) : Texture<RGBColor>
{
    public Texture<double> Scalar { get; } = scalar;
    public RGBColor Low { get; set; } = low;
    public RGBColor High { get; set; } = high;

    public override RGBColor GetValue(ShadingRecord sr)
    {
        var t = Math.Clamp(Scalar.GetValue(sr), 0, 1);
        return (1 - t) * Low + t * High;
    }
}
