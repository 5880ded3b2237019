using RayTracer.Bounds;
using RayTracer.Tracing;

namespace RayTracer.Geometry;

/// <summary>
/// A base object whose surface is kept only where a binary mask is true, e.g. a sphere keeping the
/// land of an earth map. The mask sees the shading record of the base object's hit (texture
/// coordinates and local hit point). Rejected points are skipped and the ray continues to the next
/// surface of the base object, so holes show what lies behind or inside.
/// </summary>
public sealed class BinaryObject : GeometricObject
{
    // Bound on re-shooting through rejected points (each step passes one surface crossing).
    private const int MaxSurfaceCrossings = 64;

    [ThreadStatic]
    private static ShadingRecord? _scratch;

    public BinaryObject(GeometricObject baseObject, Func<ShadingRecord, bool> mask)
    {
        BaseObject = baseObject ?? throw new ArgumentNullException(nameof(baseObject));
        Mask = mask ?? throw new ArgumentNullException(nameof(mask));
    }

    public GeometricObject BaseObject { get; }

    /// <summary>True where the surface exists.</summary>
    public Func<ShadingRecord, bool> Mask { get; }

    public override Materials.Material? Material
    {
        get => BaseObject.Material;
        set => BaseObject.Material = value;
    }

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        // The search runs on a scratch record, so a miss leaves the caller's record untouched;
        // the accepted crossing is then shaded once more into the caller's record.
        if (!Solve(ray, out tmin, out var accepted))
        {
            return false;
        }

        return BaseObject.Hit(accepted, out _, sr);
    }

    public override bool Intersect(in Ray ray, out double t) => Solve(ray, out t, out _);

    public override BoundingBox GetBoundingBox() => BaseObject.GetBoundingBox();

    /// <summary>First crossing whose point passes the mask; <paramref name="accepted"/> is the query ray that found it.</summary>
    private bool Solve(in Ray ray, out double tmin, out Ray accepted)
    {
        var sr = _scratch ??= new ShadingRecord();
        double offset = 0;
        var current = ray;
        for (int i = 0; i < MaxSurfaceCrossings; i++)
        {
            if (!BaseObject.Hit(current, out double t, sr))
            {
                break;
            }

            offset += t;
            if (Mask(sr))
            {
                tmin = offset;
                accepted = current;
                return true;
            }

            // Continue from the rejected point; t is measured along the same direction, so offsets add.
            current = new Ray(ray.At(offset), ray.d, ray.tMin);
        }

        tmin = 0;
        accepted = default;
        return false;
    }
}
