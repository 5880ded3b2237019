using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Textures.Conversions;

/// <summary>Shows a vector texture as colour, mapping each component from [-1, 1] to [0, 1] (as normal maps do).</summary>
public sealed class VectorColorTexture(Texture<Vector3D> vectors) : Texture<RGBColor>
{
    public Texture<Vector3D> Vectors { get; } = vectors;

    public override RGBColor GetValue(ShadingRecord sr)
    {
        var v = Vectors.GetValue(sr);
        return new RGBColor(
            Math.Clamp(0.5 * (v.x + 1), 0, 1),
            Math.Clamp(0.5 * (v.y + 1), 0, 1),
            Math.Clamp(0.5 * (v.z + 1), 0, 1));
    }
}
