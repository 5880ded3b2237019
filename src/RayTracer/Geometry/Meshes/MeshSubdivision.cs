using RayTracer.Maths;

namespace RayTracer.Geometry.Meshes;

/// <summary>
/// Splits every triangle into four at its edge midpoints. Each new vertex is lifted off the chord by
/// the sagitta of an arc normal to the two end normals, so a coarse mesh
/// gets rounder rather than only denser; shared edges get one midpoint, so the mesh stays closed.
/// </summary>
public static class MeshSubdivision
{
    public static Mesh Subdivide(Mesh mesh)
    {
        ArgumentNullException.ThrowIfNull(mesh);
        if (mesh.Normals is null)
            mesh.ComputeVertexNormals();
        var normals = mesh.Normals!;
        var vertices = new List<Point3D>(mesh.Vertices);
        var midpoints = new Dictionary<(int, int), int>();
        var indices = new int[mesh.Indices.Length * 4];
        var k = 0;
        for (var f = 0; f < mesh.TriangleCount; f++)
        {
            int a = mesh.Indices[3 * f], b = mesh.Indices[3 * f + 1], c = mesh.Indices[3 * f + 2];
            int ab = Midpoint(a, b), bc = Midpoint(b, c), ca = Midpoint(c, a);
            foreach (var corner in (ReadOnlySpan<int>)[a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca])
                indices[k++] = corner;
        }

        var result = new Mesh([.. vertices], indices) { TriangleTest = mesh.TriangleTest, Material = mesh.Material };
        result.ComputeVertexNormals();
        return result;

        int Midpoint(int i, int j)
        {
            var key = i < j ? (i, j) : (j, i);
            if (midpoints.TryGetValue(key, out var index))
                return index;
            Point3D p = mesh.Vertices[i], q = mesh.Vertices[j];
            Vector3D ni = normals[i].ToVector(), nj = normals[j].ToVector();
            var edge = q - p;
            // An arc from p to q normal to ni and nj bulges by about (edge · (nj − ni)) / 8 at its middle (c² / 8R on a circle).
            var lift = edge.Dot(nj - ni) / 8;
            var mean = ni + nj;
            var length = mean.Length;
            var middle = Point3D.Lerp(p, q, 0.5);
            if (length > 0)
                middle += lift / length * mean;
            index = vertices.Count;
            vertices.Add(middle);
            midpoints[key] = index;
            return index;
        }
    }

    /// <summary>The same mesh with every triangle's winding reversed when the enclosed signed volume is negative.</summary>
    public static Mesh Outward(Mesh mesh)
    {
        ArgumentNullException.ThrowIfNull(mesh);
        var volume = 0.0;
        for (var f = 0; f < mesh.TriangleCount; f++)
        {
            var a = mesh.Vertices[mesh.Indices[3 * f]].ToVector();
            var b = mesh.Vertices[mesh.Indices[3 * f + 1]].ToVector();
            var c = mesh.Vertices[mesh.Indices[3 * f + 2]].ToVector();
            volume += a.Dot(b.Cross(c));
        }

        if (volume >= 0)
            return mesh;
        var indices = (int[])mesh.Indices.Clone();
        for (var i = 0; i < indices.Length; i += 3)
            (indices[i + 1], indices[i + 2]) = (indices[i + 2], indices[i + 1]);
        return new Mesh(mesh.Vertices, indices, mesh.Normals, mesh.TextureCoordinates) { TriangleTest = mesh.TriangleTest, Material = mesh.Material };
    }
}
