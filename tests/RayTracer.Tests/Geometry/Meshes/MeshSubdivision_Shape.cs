using RayTracer.Geometry.Meshes;
using RayTracer.Maths;
using RayTracer.Scenes.Meshes;
using RayTracer.Scenes.Triangles;

namespace RayTracer.Tests.Geometry.Meshes;

public sealed class MeshSubdivision_Shape
{
    private static Mesh Icosahedron()
    {
        using var stream = new MemoryStream(System.Text.Encoding.ASCII.GetBytes(MeshesScene.IcosahedronPly()));
        var mesh = PlyReader.Read(stream, "icosahedron.ply");
        // On the unit sphere, so that the sphere's normals are the vertices themselves.
        var unit = mesh.Vertices.Select(v => Point3D.Origin + v.ToVector().Normalized()).ToArray();
        return MeshSubdivision.Outward(new Mesh(unit, mesh.Indices));
    }

    [Fact]
    public void Subdividing_a_sphere_mesh_lifts_midpoints_towards_the_sphere()
    {
        var coarse = Icosahedron();
        var fine = MeshSubdivision.Subdivide(coarse);
        Assert.Equal(4 * coarse.TriangleCount, fine.TriangleCount);
        // 12 vertices + 30 edge midpoints: every edge split once, so the mesh stays closed.
        Assert.Equal(42, fine.Vertices.Length);
        var chordMidpointRadius = 0.5 * (coarse.Vertices[0].ToVector() + coarse.Vertices[1].ToVector()).Length;
        foreach (var v in fine.Vertices.Skip(12))
        {
            var radius = v.ToVector().Length;
            Assert.True(radius > chordMidpointRadius + 0.05 && Math.Abs(radius - 1) < 0.03, $"midpoint at radius {radius}");
        }
    }

    [Fact]
    public void Outward_flips_a_mesh_wound_inwards_and_keeps_one_wound_outwards()
    {
        var outward = Icosahedron();
        var inverted = new Mesh(outward.Vertices, [.. outward.Indices.Chunk(3).SelectMany(f => new[] { f[0], f[2], f[1] })]);
        Assert.Same(outward, MeshSubdivision.Outward(outward));
        Assert.Equal(outward.Indices, MeshSubdivision.Outward(inverted).Indices);
    }

    [Fact]
    public void The_committed_bunny_is_read_whole_and_subdivided_to_about_the_thesis_count()
    {
        var bunny = TriangleTestScenes.ReadBunny();
        Assert.Equal(1839, bunny.Vertices.Length);
        Assert.Equal(3674, bunny.TriangleCount);
        Assert.Empty(bunny.Warnings);
        var subdivided = TriangleTestScenes.Bunny(detail: 0.2);
        Assert.Equal(4 * 3674, subdivided.TriangleCount);
    }
}
