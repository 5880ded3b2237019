using RayTracer.Bounds;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tracing;
using RayTracer.Transforms;

namespace RayTracer.Geometry;

/// <summary>
/// An object placed by an affine transform. The ray is mapped into the object's frame with the
/// inverse transform (t is the same on both rays because the direction is not renormalized), and
/// the normal is mapped back with the inverse transpose.
/// </summary>
public sealed class Instance : GeometricObject
{
    private Material? _material;

    public Instance(GeometricObject target, AffineTransform? transform = null)
    {
        Target = target ?? throw new ArgumentNullException(nameof(target));
        Transform = transform ?? AffineTransform.Identity;
    }

    public GeometricObject Target { get; }

    /// <summary>Object-to-world transform.</summary>
    public AffineTransform Transform { get; set; }

    /// <summary>
    /// When true, solid textures move with the object (the local hit point stays in object space);
    /// when false the local hit point is the world-space hit point.
    /// </summary>
    public bool TransformTexture { get; set; } = true;

    /// <summary>Overrides the target's material when set.</summary>
    public override Material? Material
    {
        get => _material ?? Target.Material;
        set => _material = value;
    }

    public Instance Translate(double dx, double dy, double dz) => Apply(AffineTransform.Translation(dx, dy, dz));

    public Instance Scale(double sx, double sy, double sz) => Apply(AffineTransform.Scaling(sx, sy, sz));

    public Instance Scale(double s) => Apply(AffineTransform.Scaling(s));

    public Instance RotateX(double radians) => Apply(AffineTransform.RotationX(radians));

    public Instance RotateY(double radians) => Apply(AffineTransform.RotationY(radians));

    public Instance RotateZ(double radians) => Apply(AffineTransform.RotationZ(radians));

    /// <summary>Appends <paramref name="next"/> after the current transform.</summary>
    public Instance Apply(AffineTransform next)
    {
        Transform = next * Transform;
        return this;
    }

    public override bool Intersect(in Ray ray, out double t) =>
        Target.Intersect(Transform.InverseTransformRay(ray), out t);

    public override bool ShadowHit(in Ray ray, out double tmin)
    {
        if (!CastsShadows)
        {
            tmin = 0;
            return false;
        }

        return Target.ShadowHit(Transform.InverseTransformRay(ray), out tmin);
    }

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!Target.Hit(Transform.InverseTransformRay(ray), out tmin, sr))
        {
            return false;
        }

        sr.Normal = Transform.TransformNormal(sr.Normal).Normalized();
        if (_material is not null)
        {
            sr.Material = _material;
        }

        if (!TransformTexture)
        {
            sr.LocalHitPoint = ray.At(tmin);
        }

        return true;
    }

    public override BoundingBox GetBoundingBox() => Transform.TransformBox(Target.GetBoundingBox());
}
