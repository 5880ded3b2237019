using RayTracer.Geometry.Meshes;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Tests.Geometry.Meshes;

public class MeshTriangle_Shading
{
    [Fact]
    public void Flat_triangles_use_the_face_normal_and_smooth_ones_interpolate()
    {
        var mesh = MeshSamples.Octahedron(true);
        var flat = mesh.CreateTriangles(smooth: false)[0]; // (1,0,0), (0,1,0), (0,0,1)
        var smooth = mesh.CreateTriangles(smooth: true)[0];
        var sr = new ShadingRecord();
        var centre = new Point3D(1.0 / 3, 1.0 / 3, 1.0 / 3);
        var ray = new Ray(new Point3D(2, 2, 2), centre - new Point3D(2, 2, 2));

        Assert.True(flat.Hit(ray, out double t, sr));
        Assert.Equal(1, t, 12);
        var face = new Normal3D(1, 1, 1).Normalized();
        Assert.True((sr.Normal - face).Length < 1e-12);

        // Near a corner the smooth normal approaches that vertex's normal.
        var nearCorner = new Point3D(0.98, 0.01, 0.01);
        Assert.True(smooth.Hit(new Ray(nearCorner + new Vector3D(1, 1, 1), new Vector3D(-1, -1, -1)), out _, sr));
        Assert.True(sr.Normal.x > 0.99, $"{sr.Normal}");
        // Texture coordinates interpolate the vertex (u, v): vertices 0, 2, 4 have u = 0, 0.4, 0.8.
        Assert.Equal(0.98 * 0 + 0.01 * 0.4 + 0.01 * 0.8, sr.TextureCoordinates.u, 9);
    }

    [Fact]
    public void Computed_vertex_normals_of_the_octahedron_point_along_the_vertices()
    {
        var mesh = MeshSamples.Octahedron(false);
        mesh.ComputeVertexNormals();
        for (int i = 0; i < mesh.Vertices.Length; i++)
        {
            var v = mesh.Vertices[i];
            Assert.True((mesh.Normals![i] - new Normal3D(v.x, v.y, v.z)).Length < 1e-12);
        }
    }

    [Fact]
    public void Mesh_rejects_indices_outside_its_vertices()
    {
        var mesh = MeshSamples.Octahedron(false);
        Assert.Throws<ArgumentException>(() => new Mesh(mesh.Vertices, [0, 1, 9]));
        Assert.Throws<ArgumentException>(() => new Mesh(mesh.Vertices, [0, 1]));
    }
}
