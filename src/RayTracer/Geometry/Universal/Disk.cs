using RayTracer.Bounds;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Universal;

/// <summary>Flat disk with any center, orientation and radius; one-sided normal as given.</summary>
public sealed class Disk : GeometricObject, ISampledShape
{
    private readonly OrthonormalBasis _frame;

    public Disk(Point3D center, Normal3D normal, double radius)
    {
        if (!(radius > 0) || normal.LengthSquared == 0)
        {
            throw new ArgumentException("A disk needs a positive radius and a non-zero normal.");
        }

        Center = center;
        Normal = normal.Normalized();
        Radius = radius;
        _frame = OrthonormalBasis.FromW(Normal.ToVector());
    }

    public Point3D Center { get; }

    public Normal3D Normal { get; }

    public double Radius { get; }

    public override bool Intersect(in Ray ray, out double t)
    {
        double denom = Normal.Dot(ray.d);
        t = 0;
        if (denom == 0)
        {
            return false;
        }

        t = Normal.Dot(Center - ray.o) / denom;
        return t > ray.tMin && double.IsFinite(t) && ray.At(t).DistanceSquared(Center) < Radius * Radius;
    }

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!Intersect(ray, out tmin))
        {
            return false;
        }

        var p = ray.At(tmin);
        var local = p - Center;
        double r = local.Length / Radius;
        double phi = Math.Atan2(Vector3D.Dot(local, _frame.V), Vector3D.Dot(local, _frame.U));
        if (phi < 0)
        {
            phi += MathConstants.TwoPi;
        }

        sr.Normal = Normal;
        sr.LocalHitPoint = p;
        sr.TextureCoordinates = new TextureCoordinates(phi * MathConstants.InvTwoPi, r);
        sr.Material = Material;
        return true;
    }

    public override BoundingBox GetBoundingBox()
    {
        // Extent of a disk along axis i is r·sqrt(1 - n_i²).
        var e = new Vector3D(
            Radius * Math.Sqrt(Math.Max(0, 1 - Normal.x * Normal.x)),
            Radius * Math.Sqrt(Math.Max(0, 1 - Normal.y * Normal.y)),
            Radius * Math.Sqrt(Math.Max(0, 1 - Normal.z * Normal.z)));
        return new BoundingBox(Center - e, Center + e).Expanded(Tolerances.BoundsPadding);
    }

    /// <summary>Uniform over the area: radius ∝ sqrt(u).</summary>
    public Point3D Sample(Point2D u)
    {
        double r = Radius * Math.Sqrt(u.x);
        double phi = MathConstants.TwoPi * u.y;
        return Center + _frame.ToWorld(r * Math.Cos(phi), r * Math.Sin(phi), 0);
    }

    public double Pdf(ShadingRecord sr) => 1.0 / (Math.PI * Radius * Radius);

    public Normal3D GetNormal(Point3D p) => Normal;
}
