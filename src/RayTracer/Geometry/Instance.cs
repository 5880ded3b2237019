using RayTracer.Bounds;
using RayTracer.Maths;
using RayTracer.Tracing;
using RayTracer.Transforms;

namespace RayTracer.Geometry;

/// <summary>
/// An object placed by an affine transform. The ray is mapped into the object's frame with the
/// inverse transform (t is the same on both rays because the direction is not renormalized), and
/// the normal is mapped back with the inverse transpose.
/// </summary>
public sealed class Instance : TransformedObject
{
    public Instance(GeometricObject target, AffineTransform? transform = null)
        : base(target)
    {
        Transform = transform ?? AffineTransform.Identity;
    }

    /// <summary>Object-to-world transform.</summary>
    public AffineTransform Transform { get; set; }

    /// <summary>
    /// When true, solid textures move with the object (the local hit point stays in object space);
    /// when false the local hit point is the world-space hit point.
    /// </summary>
    public bool TransformTexture { get; set; } = true;

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

    protected override Ray ToLocal(in Ray ray) => Transform.InverseTransformRay(ray);

    protected override Normal3D NormalToWorld(Normal3D n) => Transform.TransformNormal(n).Normalized();

    protected override void CompleteHit(in Ray ray, double tmin, ShadingRecord sr)
    {
        if (!TransformTexture)
            sr.LocalHitPoint = ray.At(tmin);
    }

    public override BoundingBox GetBoundingBox() => Transform.TransformBox(Target.GetBoundingBox());
}
