using RayTracer.Tracing;

namespace RayTracer.Textures.Conversions;

/// <summary>Binary texture that is true where a scalar texture exceeds <see cref="Threshold"/> (masks, spots).</summary>
public sealed class ThresholdTexture(Texture<double> scalar, double threshold) : Texture<bool>
{
    public Texture<double> Scalar { get; } = scalar;
    public double Threshold { get; set; } = threshold;

    public override bool GetValue(ShadingRecord sr) => Scalar.GetValue(sr) > Threshold;
}
