namespace RayTracer.Geometry.Meshes;

/// <summary>
/// The ray–triangle test a mesh's triangles use. All four find the same hits (up to rounding at the
/// edges) and report the same barycentric coordinates; they differ in arithmetic and stored data.
/// </summary>
public enum TriangleTest
{
    /// <summary>Möller–Trumbore: v0 and two edge vectors, early exits on each barycentric.</summary>
    MollerTrumbore,

    /// <summary>Cramer's rule on the ray and plane equations, as in the ray tracer's base book.</summary>
    Algebraic,

    /// <summary>Plücker side tests generated from PluckerRayTriangle, edge lines built per test from the vertices.</summary>
    Plucker,

    /// <summary>The Plücker test on edge lines and the plane stored per triangle (more memory, less work per test).</summary>
    PluckerEdges,
}
