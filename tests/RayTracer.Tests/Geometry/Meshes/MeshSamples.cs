using RayTracer.Geometry.Meshes;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Textures;

namespace RayTracer.Tests.Geometry.Meshes;

/// <summary>Small meshes with known geometry for file and shading tests.</summary>
internal static class MeshSamples
{
    /// <summary>Regular octahedron with unit vertices, outward winding, vertex normals and (u, v).</summary>
    public static Mesh Octahedron(bool withAttributes)
    {
        Point3D[] v =
        [
            new(1, 0, 0), new(-1, 0, 0), new(0, 1, 0), new(0, -1, 0), new(0, 0, 1), new(0, 0, -1),
        ];
        int[] faces =
        [
            0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
            2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5,
        ];
        Normal3D[]? normals = withAttributes ? [.. v.Select(p => new Normal3D(p.x, p.y, p.z))] : null;
        TextureCoordinates[]? uvs = withAttributes ? [.. v.Select((p, i) => new TextureCoordinates(i / 5.0, 0.1 * i * i + 1.0 / 3))] : null;
        return new Mesh(v, faces, normals, uvs);
    }

    /// <summary>Random soup with coordinates exactly representable as floats (binary STL stores floats).</summary>
    public static Mesh FloatExactSoup(int triangles, ulong seed)
    {
        var random = new SeededRandom(seed);
        var vertices = new Point3D[3 * triangles];
        for (int i = 0; i < vertices.Length; i++)
        {
            vertices[i] = new Point3D(
                (float)random.NextDouble(-5, 5), (float)random.NextDouble(-5, 5), (float)random.NextDouble(-5, 5));
        }

        return new Mesh(vertices, [.. Enumerable.Range(0, vertices.Length)]);
    }
}
