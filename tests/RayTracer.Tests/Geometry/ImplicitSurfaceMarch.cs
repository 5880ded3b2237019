using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Geometry;

/// <summary>
/// Brute-force reference for ray hits: march along the ray in small steps, find the first sign
/// change of the implicit function where the surface is accepted, and refine it by bisection.
/// Independent of the closed-form solvers under test.
/// </summary>
internal static class ImplicitSurfaceMarch
{
    public static double? FirstRoot(Func<Point3D, double> f, in Ray ray, double tMax, double step, Func<Point3D, bool>? accept = null)
    {
        double tPrev = 1e-6;
        double fPrev = f(ray.At(tPrev));
        for (double t = tPrev + step; t <= tMax; t += step)
        {
            double ft = f(ray.At(t));
            if (Math.Sign(ft) != Math.Sign(fPrev))
            {
                double lo = tPrev, hi = t, flo = fPrev;
                for (int i = 0; i < 80; i++)
                {
                    double mid = 0.5 * (lo + hi);
                    double fm = f(ray.At(mid));
                    if (Math.Sign(fm) == Math.Sign(flo))
                    {
                        lo = mid;
                        flo = fm;
                    }
                    else
                    {
                        hi = mid;
                    }
                }

                double root = 0.5 * (lo + hi);
                if (accept is null || accept(ray.At(root)))
                {
                    return root;
                }
            }

            tPrev = t;
            fPrev = ft;
        }

        return null;
    }

    public static Ray RandomRayTowards(SeededRandom random, double originRadius, double targetRadius)
    {
        var origin = new Point3D(
            random.NextDouble(-originRadius, originRadius), random.NextDouble(-originRadius, originRadius), random.NextDouble(-originRadius, originRadius));
        var target = new Point3D(
            random.NextDouble(-targetRadius, targetRadius), random.NextDouble(-targetRadius, targetRadius), random.NextDouble(-targetRadius, targetRadius));
        return new Ray(origin, (target - origin).Normalized());
    }
}
