using RayTracer.Acceleration;
using RayTracer.Bounds;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Parametric;

/// <summary>
/// An object made of many primitives held in one bounding volume hierarchy; every ray query goes to
/// the hierarchy, which finds the nearest primitive and lets only that one fill the shading record.
/// </summary>
public abstract class AcceleratedGroup : GeometricObject
{
    private Bvh _hierarchy = new([]);

    public int PrimitiveCount => _hierarchy.PrimitiveCount;

    public override bool CastsShadows
    {
        get => base.CastsShadows;
        set
        {
            base.CastsShadows = value;
            _hierarchy.CastsShadows = value;
        }
    }

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr) => _hierarchy.Hit(ray, out tmin, sr);

    public override bool Intersect(in Ray ray, out double t) => _hierarchy.Intersect(ray, out t);

    public override bool ShadowHit(in Ray ray, out double tmin) => _hierarchy.ShadowHit(ray, out tmin);

    public override bool Occludes(in Ray ray, double maxDistance) => _hierarchy.Occludes(ray, maxDistance);

    public override BoundingBox GetBoundingBox() => _hierarchy.GetBoundingBox();

    private protected void Build(IReadOnlyList<GeometricObject> primitives) =>
        _hierarchy = new Bvh(primitives) { CastsShadows = CastsShadows };
}
