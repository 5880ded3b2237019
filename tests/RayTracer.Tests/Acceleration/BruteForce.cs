using RayTracer.Geometry;
using RayTracer.Tracing;

namespace RayTracer.Tests.Acceleration;

/// <summary>The independent answer the acceleration structures are checked against: every object tested.</summary>
internal static class BruteForce
{
    /// <summary>The nearest hit distance over all <paramref name="objects"/>, +∞ when none is hit.</summary>
    public static double Nearest(IEnumerable<GeometricObject> objects, in Ray ray)
    {
        double best = double.PositiveInfinity;
        foreach (var o in objects)
        {
            if (o.Intersect(ray, out double t) && t < best)
                best = t;
        }

        return best;
    }
}
