using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Solvers;

/// <summary>Ray–sphere roots, shared by every sphere-shaped primitive.</summary>
public static class SphereSolver
{
    /// <summary>Both parameters where the ray's line meets the sphere (t0 ≤ t1); false if it misses.</summary>
    public static bool Intersect(in Ray ray, Point3D center, double radius, out double t0, out double t1)
    {
        var oc = ray.o - center;
        double a = ray.d.LengthSquared;
        double b = 2 * Vector3D.Dot(oc, ray.d);
        double c = oc.LengthSquared - radius * radius;
        Span<double> roots = stackalloc double[2];
        int n = PolynomialSolver.SolveQuadratic(c, b, a, roots);
        if (n == 0)
        {
            t0 = t1 = 0;
            return false;
        }

        t0 = roots[0];
        t1 = n == 2 ? roots[1] : roots[0];
        return true;
    }

    /// <summary>Smallest root greater than epsilon.</summary>
    public static bool Nearest(in Ray ray, Point3D center, double radius, out double t)
    {
        if (Intersect(ray, center, radius, out double t0, out double t1))
        {
            if (t0 > ray.tMin)
            {
                t = t0;
                return true;
            }

            if (t1 > ray.tMin)
            {
                t = t1;
                return true;
            }
        }

        t = 0;
        return false;
    }
}
