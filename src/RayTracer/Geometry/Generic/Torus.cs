using RayTracer.Bounds;
using RayTracer.Geometry.Solvers;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Generic;

/// <summary>
/// Torus about the y axis: a circle of radius <see cref="TubeRadius"/> swept around a circle of radius
/// <see cref="SweptRadius"/> in the plane y = 0, (x² + y² + z² + a² - b²)² = 4a² (x² + z²).
/// </summary>
public class Torus : GeometricObject
{
    private readonly BoundingBox _bounds;

    public Torus(double sweptRadius, double tubeRadius)
    {
        if (!(sweptRadius > 0) || !(tubeRadius > 0))
        {
            throw new ArgumentException("A torus needs positive swept and tube radii.");
        }

        SweptRadius = sweptRadius;
        TubeRadius = tubeRadius;
        double e = sweptRadius + tubeRadius;
        _bounds = new BoundingBox(-e, e, -tubeRadius, tubeRadius, -e, e);
    }

    public double SweptRadius { get; }

    public double TubeRadius { get; }

    public override bool Intersect(in Ray ray, out double t) => Solve(ray, out t);

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr)
    {
        if (!Solve(ray, out tmin))
        {
            return false;
        }

        var p = ray.At(tmin);
        var n = NormalAt(p);
        if (FaceRay && n.Dot(ray.d) > 0)
        {
            n = -n;
        }

        double ringX = p.x, ringZ = p.z;
        double ring = Math.Sqrt(ringX * ringX + ringZ * ringZ);
        double tubeAngle = Math.Atan2(p.y, ring - SweptRadius);
        if (tubeAngle < 0)
        {
            tubeAngle += MathConstants.TwoPi;
        }

        sr.Normal = n;
        sr.LocalHitPoint = p;
        sr.TextureCoordinates = new TextureCoordinates(
            Azimuth.Of(p.x, p.z) * MathConstants.InvTwoPi, tubeAngle * MathConstants.InvTwoPi);
        sr.Material = Material;
        return true;
    }

    public override BoundingBox GetBoundingBox() => _bounds;

    /// <summary>Outward unit normal (gradient of the implicit quartic).</summary>
    public Normal3D NormalAt(Point3D p)
    {
        double param = SweptRadius * SweptRadius + TubeRadius * TubeRadius;
        double sum = p.x * p.x + p.y * p.y + p.z * p.z;
        var n = new Normal3D(
            p.x * (sum - param),
            p.y * (sum - param + 2 * SweptRadius * SweptRadius),
            p.z * (sum - param));
        return n.Normalized();
    }

    /// <summary>Whether the normal is turned towards the viewer (open part tori) rather than kept outward.</summary>
    protected virtual bool FaceRay => false;

    /// <summary>Part tori restrict which points of the full surface count.</summary>
    protected virtual bool Accept(Point3D p) => true;

    private bool Solve(in Ray ray, out double t)
    {
        t = 0;
        if (!_bounds.Hit(ray, out double tEnter, out _))
        {
            return false;
        }

        // Solving from a point near the torus keeps the quartic's coefficients of similar size;
        // from far away they differ by many orders of magnitude and the roots lose accuracy.
        double shift = Math.Max(0, tEnter);
        var o = ray.At(shift);
        var d = ray.d;

        double a2 = SweptRadius * SweptRadius;
        double dd = d.LengthSquared;
        double e = o.x * o.x + o.y * o.y + o.z * o.z - a2 - TubeRadius * TubeRadius;
        double f = o.x * d.x + o.y * d.y + o.z * d.z;
        double fourA2 = 4 * a2;

        Span<double> roots = stackalloc double[4];
        int n = PolynomialSolver.SolveQuartic(
            e * e - fourA2 * (TubeRadius * TubeRadius - o.y * o.y),
            4 * f * e + 2 * fourA2 * o.y * d.y,
            2 * dd * e + 4 * f * f + fourA2 * d.y * d.y,
            4 * dd * f,
            dd * dd,
            roots);

        for (int i = 0; i < n; i++)
        {
            double ti = roots[i] + shift;
            if (ti > ray.tMin && Accept(ray.At(ti)))
            {
                t = ti;
                return true;
            }
        }

        return false;
    }
}
