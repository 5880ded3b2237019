using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Geometry;

/// <summary>
/// An object seen through a placement: the ray is taken into the target's frame (keeping t, as the direction
/// is not renormalised) and the hit normal back to the world. Subclasses differ only in those two maps
/// (a general affine transform, a TSR versor, an RSTR mirror); hits, shadow hits and the material override
/// are shared here.
/// </summary>
public abstract class TransformedObject : GeometricObject
{
    private Material? _material;

    protected TransformedObject(GeometricObject target)
    {
        Target = target ?? throw new ArgumentNullException(nameof(target));
    }

    public GeometricObject Target { get; }

    /// <summary>Overrides the target's material when set.</summary>
    public override Material? Material
    {
        get => _material ?? Target.Material;
        set => _material = value;
    }

    /// <summary>The world ray in the target's frame, with the same t along it.</summary>
    protected abstract Ray ToLocal(in Ray ray);

    /// <summary>A normal of the target, carried to the world (normals map by the inverse transpose).</summary>
    protected abstract Normal3D NormalToWorld(Normal3D n);

    /// <summary>Anything a placement adds to a hit record once the normal and material are set.</summary>
    protected virtual void CompleteHit(in Ray ray, double tmin, ShadingRecord sr)
    {
    }

    public sealed override bool Intersect(in Ray ray, out double t) => Target.Intersect(ToLocal(ray), out t);

    public sealed override bool ShadowHit(in Ray ray, out double tmin)
    {
        if (!CastsShadows)
        {
            tmin = 0;
            return false;
        }
        return Target.ShadowHit(ToLocal(ray), out tmin);
    }

    public sealed override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!Target.Hit(ToLocal(ray), out tmin, sr))
            return false;
        sr.Normal = NormalToWorld(sr.Normal);
        if (_material is not null)
            sr.Material = _material;
        CompleteHit(ray, tmin, sr);
        return true;
    }
}
