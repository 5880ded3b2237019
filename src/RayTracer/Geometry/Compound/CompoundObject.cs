using RayTracer.Bounds;
using RayTracer.Materials;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Compound;

/// <summary>
/// A group of objects hit as one. The nearest part is found with the cheap distance test and only
/// that part fills the shading record, so a farther part can never leave stale data in it.
/// </summary>
public class CompoundObject : GeometricObject
{
    private readonly List<GeometricObject> _parts = [];
    private BoundingBox _bounds = BoundingBox.Empty;

    public IReadOnlyList<GeometricObject> Parts => _parts;

    /// <summary>Setting a material on the compound gives it to every part (Suffern's convention).</summary>
    public override Material? Material
    {
        get => base.Material;
        set
        {
            base.Material = value;
            foreach (var part in _parts)
            {
                part.Material = value;
            }
        }
    }

    public void Add(GeometricObject part)
    {
        ArgumentNullException.ThrowIfNull(part);
        _parts.Add(part);
        _bounds.Include(part.GetBoundingBox());
    }

    public override bool Intersect(in Ray ray, out double t) => Nearest(ray, out t) is not null;

    public override bool ShadowHit(in Ray ray, out double tmin)
    {
        tmin = double.PositiveInfinity;
        if (!CastsShadows || !MayHit(ray))
        {
            tmin = 0;
            return false;
        }

        bool any = false;
        foreach (var part in _parts)
        {
            if (part.ShadowHit(ray, out double t) && t < tmin)
            {
                tmin = t;
                any = true;
            }
        }

        return any;
    }

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        var nearest = Nearest(ray, out _);
        if (nearest is null)
        {
            tmin = 0;
            return false;
        }

        return nearest.Hit(ray, out tmin, sr);
    }

    public override BoundingBox GetBoundingBox() => _bounds;

    private bool MayHit(in Ray ray) => !_bounds.IsFinite || _bounds.Hit(ray, out _, out _);

    private GeometricObject? Nearest(in Ray ray, out double tmin)
    {
        tmin = double.PositiveInfinity;
        if (!MayHit(ray))
        {
            return null;
        }

        GeometricObject? nearest = null;
        foreach (var part in _parts)
        {
            if (part.Intersect(ray, out double t) && t < tmin)
            {
                tmin = t;
                nearest = part;
            }
        }

        return nearest;
    }
}
