using RayTracer.Bounds;
using RayTracer.Kernels;
using RayTracer.Maths;
using RayTracer.Textures;

namespace RayTracer.Geometry.Meshes;

/// <summary>
/// Indexed triangle mesh: shared vertices, optional per-vertex normals and (u, v), three indices per
/// triangle. As an <see cref="ObjectNature"/> it holds the material shared by all its triangles.
/// </summary>
public sealed class Mesh : ObjectNature
{
    public Mesh(Point3D[] vertices, int[] indices, Normal3D[]? normals = null, TextureCoordinates[]? uvs = null)
    {
        ArgumentNullException.ThrowIfNull(vertices);
        ArgumentNullException.ThrowIfNull(indices);
        if (indices.Length % 3 != 0)
        {
            throw new ArgumentException("The index count must be a multiple of three.", nameof(indices));
        }

        for (int i = 0; i < indices.Length; i++)
        {
            if ((uint)indices[i] >= (uint)vertices.Length)
            {
                throw new ArgumentException($"Index {indices[i]} of triangle {i / 3} is outside the {vertices.Length} vertices.", nameof(indices));
            }
        }

        if (normals is not null && normals.Length != vertices.Length)
        {
            throw new ArgumentException("There must be one normal per vertex.", nameof(normals));
        }

        if (uvs is not null && uvs.Length != vertices.Length)
        {
            throw new ArgumentException("There must be one (u, v) per vertex.", nameof(uvs));
        }

        Vertices = vertices;
        Indices = indices;
        Normals = normals;
        TextureCoordinates = uvs;
    }

    public Point3D[] Vertices { get; }

    public int[] Indices { get; }

    public Normal3D[]? Normals { get; private set; }

    public TextureCoordinates[]? TextureCoordinates { get; }

    public int TriangleCount => Indices.Length / 3;

    /// <summary>
    /// The ray–triangle test of this mesh's triangles (Möller–Trumbore unless set). Triangles take it
    /// when <see cref="CreateTriangles"/> makes them, so set it before.
    /// </summary>
    public TriangleTest TriangleTest { get; set; } = TriangleTest.MollerTrumbore;

    /// <summary>
    /// Problems the reader tolerated in the file this mesh came from, each as <c>file(line): message</c>;
    /// empty for meshes built in code.
    /// </summary>
    public IReadOnlyList<string> Warnings { get; init; } = [];

    public BoundingBox Bounds
    {
        get
        {
            var box = BoundingBox.Empty;
            foreach (var v in Vertices)
            {
                box.Include(v);
            }

            return box;
        }
    }

    /// <summary>Per-vertex normals as area-weighted averages of the adjacent face normals.</summary>
    public void ComputeVertexNormals()
    {
        var sums = new Vector3D[Vertices.Length];
        for (int f = 0; f < TriangleCount; f++)
        {
            int a = Indices[3 * f], b = Indices[3 * f + 1], c = Indices[3 * f + 2];
            // The cross product's length is twice the area, which gives the weighting for free.
            var n = TriangleNormal.Of(Vertices[a], Vertices[b], Vertices[c]);
            sums[a] += n;
            sums[b] += n;
            sums[c] += n;
        }

        var normals = new Normal3D[Vertices.Length];
        for (int i = 0; i < normals.Length; i++)
        {
            double len = sums[i].Length;
            normals[i] = len > 0 ? new Normal3D(sums[i] / len) : new Normal3D(0, 1, 0);
        }

        Normals = normals;
    }

    /// <summary>One primitive per triangle; smooth triangles interpolate vertex normals (computed if absent).</summary>
    public MeshTriangle[] CreateTriangles(bool smooth)
    {
        if (smooth && Normals is null)
        {
            ComputeVertexNormals();
        }

        var triangles = new MeshTriangle[TriangleCount];
        for (int f = 0; f < triangles.Length; f++)
        {
            triangles[f] = new MeshTriangle(this, f, smooth);
        }

        return triangles;
    }
}
