using RayTracer.Bounds;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Universal;

/// <summary>Parallelogram p0 + u a + v b, u, v ∈ [0, 1], with normal along a × b.</summary>
public sealed class Rectangle : GeometricObject, ISampledShape
{
    private readonly double _aLengthSquared;
    private readonly double _bLengthSquared;

    public Rectangle(Point3D corner, Vector3D a, Vector3D b)
    {
        var n = Vector3D.Cross(a, b);
        if (n.LengthSquared == 0)
        {
            throw new ArgumentException("Rectangle sides must be non-zero and not parallel.");
        }

        Corner = corner;
        A = a;
        B = b;
        Normal = new Normal3D(n.Normalized());
        Area = n.Length;
        _aLengthSquared = a.LengthSquared;
        _bLengthSquared = b.LengthSquared;
    }

    /// <summary>Same rectangle with the normal flipped.</summary>
    public Rectangle(Point3D corner, Vector3D a, Vector3D b, Normal3D normal) : this(corner, a, b)
    {
        if (normal.Dot(Normal) < 0)
        {
            Normal = -Normal;
        }
    }

    public Point3D Corner { get; }

    public Vector3D A { get; }

    public Vector3D B { get; }

    public Normal3D Normal { get; }

    public double Area { get; }

    public override bool Intersect(in Ray ray, out double t) => Solve(ray, out t, out _, out _);

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!Solve(ray, out tmin, out double u, out double v))
        {
            return false;
        }

        sr.Normal = Normal;
        sr.LocalHitPoint = ray.At(tmin);
        sr.TextureCoordinates = new TextureCoordinates(u, v);
        sr.Material = Material;
        return true;
    }

    public override BoundingBox GetBoundingBox()
    {
        var box = BoundingBox.Empty;
        box.Include(Corner);
        box.Include(Corner + A);
        box.Include(Corner + B);
        box.Include(Corner + A + B);
        return box.Expanded(Tolerances.BoundsPadding);
    }

    public Point3D Sample(Point2D u) => Corner + u.x * A + u.y * B;

    public double Pdf(ShadingRecord sr) => 1.0 / Area;

    public Normal3D GetNormal(Point3D p) => Normal;

    private bool Solve(in Ray ray, out double t, out double u, out double v)
    {
        u = v = 0;
        double denom = Normal.Dot(ray.d);
        t = denom == 0 ? 0 : Normal.Dot(Corner - ray.o) / denom;
        if (denom == 0 || !(t > ray.tMin) || !double.IsFinite(t))
        {
            return false;
        }

        var d = ray.At(t) - Corner;
        u = Vector3D.Dot(d, A) / _aLengthSquared;
        v = Vector3D.Dot(d, B) / _bLengthSquared;
        return u >= 0 && u <= 1 && v >= 0 && v <= 1;
    }
}
