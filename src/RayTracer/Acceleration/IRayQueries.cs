using RayTracer.Tracing;

namespace RayTracer.Acceleration;

/// <summary>
/// The two ray queries of a structure over a scene's primitives, apart from how the primitives are
/// reached: what our structures and a foreign library (Embree) both answer, so one timing loop serves both.
/// </summary>
public interface IRayQueries
{
    /// <summary>Nearest hit with t in (epsilon, <paramref name="tMax"/>): its distance and primitive index.</summary>
    bool IntersectNearest(in Ray ray, double tMax, out double t, out int primitive);

    /// <summary>Whether any shadow-casting primitive is hit with t in (epsilon, <paramref name="tMax"/>); stops at the first one found.</summary>
    bool IntersectAny(in Ray ray, double tMax);
}
