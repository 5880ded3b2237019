using RayTracer.Bounds;
using RayTracer.Geometry.Solvers;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Generic;

/// <summary>
/// Open cone with its base circle (radius r) in the plane y = 0 and apex at (0, h, 0):
/// x² + z² = (r/h)² (h - y)², 0 ≤ y ≤ h.
/// </summary>
public sealed class Cone : GeometricObject
{
    private readonly double _k;

    public Cone(double height, double radius)
    {
        if (!(height > 0) || !(radius > 0))
        {
            throw new ArgumentException("A cone needs a positive height and radius.");
        }

        Height = height;
        Radius = radius;
        _k = radius / height * (radius / height);
    }

    public double Height { get; }

    public double Radius { get; }

    public bool NormalFacesRay { get; set; } = true;

    public override bool Intersect(in Ray ray, out double t) => Solve(ray, out t);

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!Solve(ray, out tmin))
        {
            return false;
        }

        var p = ray.At(tmin);
        // Gradient of x² + z² - k (h - y)².
        var n = new Normal3D(p.x, _k * (Height - p.y), p.z);
        n.Normalize();
        if (NormalFacesRay && n.Dot(ray.d) > 0)
        {
            n = -n;
        }

        sr.Normal = n;
        sr.LocalHitPoint = p;
        sr.TextureCoordinates = new TextureCoordinates(Azimuth.Of(p.x, p.z) * MathConstants.InvTwoPi, p.y / Height);
        sr.Material = Material;
        return true;
    }

    public override BoundingBox GetBoundingBox() => new(-Radius, Radius, 0, Height, -Radius, Radius);

    private bool Solve(in Ray ray, out double t)
    {
        double hy = Height - ray.o.y;
        Span<double> roots = stackalloc double[2];
        int n = PolynomialSolver.SolveQuadratic(
            ray.o.x * ray.o.x + ray.o.z * ray.o.z - _k * hy * hy,
            2 * (ray.o.x * ray.d.x + ray.o.z * ray.d.z + _k * hy * ray.d.y),
            ray.d.x * ray.d.x + ray.d.z * ray.d.z - _k * ray.d.y * ray.d.y,
            roots);
        for (int i = 0; i < n; i++)
        {
            // The quadric is a double cone; keep the nappe between base and apex.
            double y = ray.o.y + roots[i] * ray.d.y;
            if (roots[i] > ray.tMin && y >= 0 && y <= Height)
            {
                t = roots[i];
                return true;
            }
        }

        t = 0;
        return false;
    }
}
