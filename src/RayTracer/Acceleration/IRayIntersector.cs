using RayTracer.Geometry;
using RayTracer.Tracing;

namespace RayTracer.Acceleration;

/// <summary>The small query interface shared by every acceleration structure.</summary>
public interface IRayIntersector : IRayQueries
{
    /// <summary>Number of primitives the structure was built over (bounded and unbounded).</summary>
    int PrimitiveCount { get; }

    GeometricObject GetPrimitive(int index);
}
