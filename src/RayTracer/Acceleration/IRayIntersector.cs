using RayTracer.Geometry;
using RayTracer.Tracing;

namespace RayTracer.Acceleration;

/// <summary>The small query interface shared by every acceleration structure.</summary>
public interface IRayIntersector
{
    /// <summary>Number of primitives the structure was built over (bounded and unbounded).</summary>
    int PrimitiveCount { get; }

    GeometricObject GetPrimitive(int index);

    /// <summary>Nearest hit with t in (epsilon, <paramref name="tMax"/>): its distance and primitive index.</summary>
    bool IntersectNearest(in Ray ray, double tMax, out double t, out int primitive);

    /// <summary>Whether any shadow-casting primitive is hit with t in (epsilon, <paramref name="tMax"/>); stops at the first one found.</summary>
    bool IntersectAny(in Ray ray, double tMax);
}
