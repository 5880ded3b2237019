using RayTracer.Bounds;
using RayTracer.Geometry.Solvers;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Universal;

/// <summary>Sphere with any center and radius. Normals point outward, also for rays starting inside.</summary>
public sealed class Sphere : GeometricObject, ISampledShape
{
    public Sphere(Point3D center, double radius)
    {
        if (!(radius > 0))
        {
            throw new ArgumentOutOfRangeException(nameof(radius), radius, "A sphere needs a positive radius.");
        }

        Center = center;
        Radius = radius;
    }

    public Point3D Center { get; }

    public double Radius { get; }

    public override bool Intersect(in Ray ray, out double t) => SphereSolver.Nearest(ray, Center, Radius, out t);

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!SphereSolver.Nearest(ray, Center, Radius, out tmin))
        {
            return false;
        }

        var p = ray.At(tmin);
        var n = new Normal3D((p - Center) / Radius);
        n.Normalize();
        sr.Normal = n;
        sr.LocalHitPoint = p;
        sr.TextureCoordinates = SphericalCoordinates(n);
        sr.Material = Material;
        return true;
    }

    public override BoundingBox GetBoundingBox() => new(Center - new Vector3D(Radius), Center + new Vector3D(Radius));

    /// <summary>Uniform on the surface: z uniform in [-1, 1] (Archimedes), azimuth uniform.</summary>
    public Point3D Sample(Point2D u)
    {
        double z = 1 - 2 * u.x;
        double r = Math.Sqrt(Math.Max(0, 1 - z * z));
        double phi = MathConstants.TwoPi * u.y;
        return Center + Radius * new Vector3D(r * Math.Cos(phi), r * Math.Sin(phi), z);
    }

    public double Pdf(ShadingRecord sr) => 1.0 / (4 * Math.PI * Radius * Radius);

    public Normal3D GetNormal(Point3D p) => new Normal3D(p - Center).Normalized();

    /// <summary>u from the azimuth about +y measured from +z, v from the pole angle (1 at +y), as in Suffern's spherical map.</summary>
    internal static TextureCoordinates SphericalCoordinates(Normal3D n)
    {
        double phi = Math.Atan2(n.x, n.z);
        if (phi < 0)
        {
            phi += MathConstants.TwoPi;
        }

        double theta = Math.Acos(Math.Clamp(n.y, -1, 1));
        return new TextureCoordinates(phi * MathConstants.InvTwoPi, 1 - theta * MathConstants.InvPi);
    }
}
