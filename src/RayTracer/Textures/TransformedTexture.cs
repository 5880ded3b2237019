using RayTracer.Tracing;
using RayTracer.Transforms;

namespace RayTracer.Textures;

/// <summary>
/// Moves, rotates or scales another texture by evaluating it at the inverse-transformed local hit point,
/// so one solid or mapped texture can be placed differently on each object.
/// </summary>
public sealed class TransformedTexture<T>(Texture<T> inner, AffineTransform transform) : Texture<T>
{
    public Texture<T> Inner { get; } = inner;
    public AffineTransform Transform { get; set; } = transform;

    public override T GetValue(ShadingRecord sr)
    {
        var original = sr.LocalHitPoint;
        sr.LocalHitPoint = Transform.InverseTransformPoint(original);
        try
        {
            return Inner.GetValue(sr);
        }
        finally
        {
            sr.LocalHitPoint = original;
        }
    }
}
