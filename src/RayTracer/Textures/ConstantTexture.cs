using RayTracer.Tracing;

namespace RayTracer.Textures;

/// <summary>The same value everywhere (a plain colour, scalar, flag or vector).</summary>
public sealed class ConstantTexture<T>(T value) : Texture<T>
{
    public T Value { get; set; } = value;

    public override T GetValue(ShadingRecord sr) => Value;
}
