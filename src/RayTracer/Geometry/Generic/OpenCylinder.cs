using RayTracer.Bounds;
using RayTracer.Geometry.Solvers;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Generic;

/// <summary>Tube x² + z² = r², bottom ≤ y ≤ top, without caps; place it elsewhere with an <see cref="Instance"/>.</summary>
public class OpenCylinder : GeometricObject
{
    public OpenCylinder(double bottom, double top, double radius)
    {
        if (!(radius > 0) || !(top > bottom))
        {
            throw new ArgumentException("An open cylinder needs radius > 0 and top > bottom.");
        }

        Bottom = bottom;
        Top = top;
        Radius = radius;
    }

    public double Bottom { get; }

    public double Top { get; }

    public double Radius { get; }

    /// <summary>When the inside is hit, turn the normal towards the viewer so the inner wall shades; solids turn this off.</summary>
    public bool NormalFacesRay { get; set; } = true;

    public override bool Intersect(in Ray ray, out double t) => Solve(ray, out t);

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!Solve(ray, out tmin))
        {
            return false;
        }

        var p = ray.At(tmin);
        var n = new Normal3D(p.x / Radius, 0, p.z / Radius);
        n.Normalize();
        if (NormalFacesRay && n.Dot(ray.d) > 0)
        {
            n = -n;
        }

        sr.Normal = n;
        sr.LocalHitPoint = p;
        sr.TextureCoordinates = new TextureCoordinates(
            Azimuth.Of(p.x, p.z) * MathConstants.InvTwoPi, (p.y - Bottom) / (Top - Bottom));
        sr.Material = Material;
        return true;
    }

    public override BoundingBox GetBoundingBox() =>
        new(-Radius, Radius, Bottom, Top, -Radius, Radius);

    /// <summary>Whether a point on the infinite tube belongs to this object (part cylinders restrict the azimuth).</summary>
    protected virtual bool Accept(Point3D p) => p.y >= Bottom && p.y <= Top;

    private bool Solve(in Ray ray, out double t)
    {
        Span<double> roots = stackalloc double[2];
        int n = PolynomialSolver.SolveQuadratic(
            ray.o.x * ray.o.x + ray.o.z * ray.o.z - Radius * Radius,
            2 * (ray.o.x * ray.d.x + ray.o.z * ray.d.z),
            ray.d.x * ray.d.x + ray.d.z * ray.d.z,
            roots);
        for (int i = 0; i < n; i++)
        {
            if (roots[i] > ray.tMin && Accept(ray.At(roots[i])))
            {
                t = roots[i];
                return true;
            }
        }

        t = 0;
        return false;
    }
}
