namespace Twister.Tessellation;

/// <summary>
/// A tessellated surface: per vertex a position, a unit normal and its (u, v); three indices per
/// triangle, wound counter-clockwise in (u, v), so the triangles face the way the surface normal does.
/// <para>
/// Seams: where a surface closes on itself (u = 0 meets u = 1, or v = 0 meets v = 1) and where a
/// whole parameter edge collapses to one point (the poles of a sphere), the mesh keeps one vertex
/// per (u, v), so the texture coordinates stay right, but those vertices have identical positions and
/// normals. <see cref="Welded"/> maps each vertex to the one vertex that stands for its position;
/// through it the mesh of a closed surface is closed: every edge has exactly two triangles. Triangles
/// that the weld would flatten to a segment (the slivers at a pole) are left out.
/// </para>
/// </summary>
public sealed class TriangleMesh
{
    internal TriangleMesh(TwistablePoint[] positions, TwistableVector[] normals, SurfaceParameter[] parameters, int[] indices, int[] welded)
    {
        Positions = positions;
        Normals = normals;
        Parameters = parameters;
        Indices = indices;
        Welded = welded;
    }

    public IReadOnlyList<TwistablePoint> Positions { get; }

    /// <summary>Unit normals from <see cref="IParametricSurface.NormalAt"/>; where it vanishes, the average of nearby normals.</summary>
    public IReadOnlyList<TwistableVector> Normals { get; }

    public IReadOnlyList<SurfaceParameter> Parameters { get; }

    public IReadOnlyList<int> Indices { get; }

    /// <summary>For each vertex, the vertex that stands for its position on a seam or pole (itself elsewhere).</summary>
    public IReadOnlyList<int> Welded { get; }

    public int VertexCount => Positions.Count;

    public int TriangleCount => Indices.Count / 3;
}
