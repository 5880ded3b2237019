using RayTracer.Textures.Mappings;
using RayTracer.Tracing;

namespace RayTracer.Textures;

/// <summary>
/// A texture defined on 2D texture space. (u, v) come from <see cref="Mapping"/> applied to the local hit
/// point, or from the object's own texture coordinates when there is no mapping.
/// </summary>
public abstract class UVTexture<T> : Texture<T>, IUVMapped<T>
{
    public TextureMapping? Mapping { get; set; }

    public abstract T Evaluate(double u, double v);

    public override T GetValue(ShadingRecord sr)
    {
        var uv = Mapping?.Map(sr.LocalHitPoint) ?? sr.TextureCoordinates;
        return Evaluate(uv.u, uv.v);
    }
}
