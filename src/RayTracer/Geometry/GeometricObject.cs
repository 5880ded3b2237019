using RayTracer.Bounds;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Geometry;

/// <summary>Base of everything a ray can hit: primitives, compounds, instances, acceleration structures.</summary>
public abstract class GeometricObject
{
    /// <summary>Virtual so compound objects can hand a material down to their parts.</summary>
    public virtual Material? Material { get; set; }

    /// <summary>Virtual so that parts of a shared nature (mesh triangles) can also consult it.</summary>
    public virtual bool CastsShadows { get; set; } = true;

    [ThreadStatic]
    private static ShadingRecord? _scratch;

    /// <summary>
    /// Nearest hit with t greater than <see cref="Ray.tMin"/>. On a hit the object fills
    /// <paramref name="sr"/>'s Normal (unit), LocalHitPoint, TextureCoordinates and Material (the
    /// material of the part actually hit, which for compounds and meshes is not this object's own);
    /// the caller sets HitAnObject, HitPoint, T and Ray. On a miss <paramref name="sr"/> is untouched.
    /// </summary>
    public abstract bool Hit(in Ray ray, out double tmin, ShadingRecord sr);

    /// <summary>
    /// Nearest hit distance only. Acceleration structures call this while traversing and call
    /// <see cref="Hit"/> once for the winner. Primitives override it with a cheaper test.
    /// </summary>
    public virtual bool Intersect(in Ray ray, out double t) => Hit(ray, out t, _scratch ??= new ShadingRecord());

    /// <summary>Hit with t greater than epsilon for shadow rays; false when the object casts no shadows.</summary>
    public virtual bool ShadowHit(in Ray ray, out double tmin)
    {
        if (!CastsShadows)
        {
            tmin = 0;
            return false;
        }

        return Intersect(ray, out tmin);
    }

    /// <summary>
    /// Whether a shadow-casting surface lies on the ray with t in (epsilon, <paramref name="maxDistance"/>).
    /// Acceleration structures answer this by stopping at the first hit they find, so lights that
    /// know the distance to the light should call this rather than <see cref="ShadowHit(in Ray, out double)"/>.
    /// </summary>
    public virtual bool Occludes(in Ray ray, double maxDistance) =>
        ShadowHit(ray, out double t) && t < maxDistance;

    /// <summary>World-space bounds; unbounded objects return <see cref="BoundingBox.Infinite"/>.</summary>
    public abstract BoundingBox GetBoundingBox();
}
