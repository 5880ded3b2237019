using RayTracer.Geometry.Meshes;
using RayTracer.Maths;

namespace RayTracer.Geometry;

/// <summary>
/// A primitive whose hit distance is exactly the flat triangle (V0, V1, V2). Acceleration structures
/// copy these vertices into packed arrays and intersect them without a virtual call.
/// </summary>
public interface ITriangle
{
    Point3D V0 { get; }

    Point3D V1 { get; }

    Point3D V2 { get; }

    /// <summary>The ray–triangle test to run on this triangle.</summary>
    TriangleTest Test => TriangleTest.MollerTrumbore;
}
