using RayTracer.Bounds;
using RayTracer.Geometry;
using RayTracer.Tracing;

namespace RayTracer.Acceleration;

/// <summary>
/// Base of the acceleration structures. It is itself a <see cref="GeometricObject"/>, so a world can
/// hold one like any other object: traversal finds the nearest primitive with the cheap distance
/// test, and only that primitive fills the shading record.
/// </summary>
public abstract class AccelerationStructure : GeometricObject, IRayIntersector
{
    private protected AccelerationStructure(IReadOnlyList<GeometricObject> objects)
    {
        Table = new PrimitiveTable(objects);
    }

    private protected PrimitiveTable Table { get; }

    public int PrimitiveCount => Table.TotalCount;

    public GeometricObject GetPrimitive(int index) => Table.Get(index);

    public bool IntersectNearest(in Ray ray, double tMax, out double t, out int primitive)
    {
        t = tMax;
        primitive = -1;
        bool hit = Table.Count > 0 && TraverseNearest(ray, ref t, ref primitive);
        hit |= Table.IntersectUnbounded(ray, ref t, ref primitive);
        if (!hit)
        {
            t = 0;
        }

        return hit;
    }

    public bool IntersectAny(in Ray ray, double tMax) =>
        (Table.Count > 0 && TraverseAny(ray, tMax)) || Table.OccludedByUnbounded(ray, tMax);

    public override bool Intersect(in Ray ray, out double t) =>
        IntersectNearest(ray, double.PositiveInfinity, out t, out _);

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!IntersectNearest(ray, double.PositiveInfinity, out _, out int primitive))
        {
            tmin = 0;
            return false;
        }

        return Table.Get(primitive).Hit(ray, out tmin, sr);
    }

    /// <summary>Nearest shadow-casting hit (exhaustive). Lights that know the distance to the light should prefer <see cref="IntersectAny"/>.</summary>
    public override bool ShadowHit(in Ray ray, out double tmin)
    {
        tmin = 0;
        if (!CastsShadows || !IntersectNearest(ray, double.PositiveInfinity, out double t, out int primitive))
        {
            return false;
        }

        var nearest = Table.Get(primitive);
        if (nearest.CastsShadows && nearest.ShadowHit(ray, out tmin))
        {
            return true;
        }

        // The nearest surface casts no shadow; fall back to a full search among those that do.
        return ShadowHitExhaustive(ray, out tmin);
    }

    public override bool Occludes(in Ray ray, double maxDistance) => CastsShadows && IntersectAny(ray, maxDistance);

    public override BoundingBox GetBoundingBox() =>
        Table.Unbounded.Length > 0 ? BoundingBox.Infinite : Table.SceneBounds;

    /// <summary>Searches the bounded primitives; t holds the current limit and is lowered on every closer hit.</summary>
    private protected abstract bool TraverseNearest(in Ray ray, ref double t, ref int primitive);

    private protected abstract bool TraverseAny(in Ray ray, double tMax);

    private bool ShadowHitExhaustive(in Ray ray, out double tmin)
    {
        tmin = double.PositiveInfinity;
        for (int i = 0; i < Table.TotalCount; i++)
        {
            if (Table.Get(i).ShadowHit(ray, out double t) && t < tmin)
            {
                tmin = t;
            }
        }

        return tmin < double.PositiveInfinity;
    }
}
