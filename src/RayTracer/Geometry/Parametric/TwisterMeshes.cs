using RayTracer.Geometry.Meshes;
using RayTracer.Maths;
using RayTracer.Textures;
using Twister.Tessellation;

namespace RayTracer.Geometry.Parametric;

/// <summary>Conversion of Twister's tessellated surfaces into the ray tracer's meshes.</summary>
public static class TwisterMeshes
{
    /// <summary>
    /// The same vertices, triangles and unit normals, with each vertex's (u, v) as its texture
    /// coordinates, so (u, v) textures show the surface's parametrization. Seam and pole copies stay
    /// separate vertices (their texture coordinates differ) at identical positions.
    /// </summary>
    public static Mesh ToMesh(TriangleMesh tessellation)
    {
        ArgumentNullException.ThrowIfNull(tessellation);
        var count = tessellation.VertexCount;
        var vertices = new Point3D[count];
        var normals = new Normal3D[count];
        var uvs = new TextureCoordinates[count];
        for (var i = 0; i < count; i++)
        {
            var p = tessellation.Positions[i];
            var n = tessellation.Normals[i];
            var uv = tessellation.Parameters[i];
            vertices[i] = new Point3D(p.x, p.y, p.z);
            normals[i] = new Normal3D(n.x, n.y, n.z);
            uvs[i] = new TextureCoordinates(uv.U, uv.V);
        }

        return new Mesh(vertices, [.. tessellation.Indices], normals, uvs);
    }
}
