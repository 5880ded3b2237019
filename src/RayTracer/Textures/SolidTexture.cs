using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Textures;

/// <summary>A texture defined on 3D space, evaluated at the local hit point (carved out of a solid block).</summary>
public abstract class SolidTexture<T> : Texture<T>, IUVWMapped<T>
{
    public abstract T Evaluate(Point3D p);

    public override T GetValue(ShadingRecord sr) => Evaluate(sr.LocalHitPoint);
}
