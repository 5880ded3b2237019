using Twister.Tessellation;
using Twister.Tests.Tessellation.Shapes;

namespace Twister.Tests.Tessellation;

public class SurfaceTessellator_Seams
{
    public static TheoryData<string, double, int> ClosedSurfaces => new()
    {
        // name, tolerance, Euler characteristic V − E + F
        { "sphere", 1e-2, 2 },
        { "sphere", 2e-3, 2 },
        { "torus", 1e-2, 0 },
        { "torus", 2e-3, 0 },
    };

    [Theory]
    [MemberData(nameof(ClosedSurfaces))]
    public void A_closed_surface_welds_into_a_closed_mesh_with_every_edge_shared_by_two_triangles(string name, double tolerance, int euler)
    {
        var mesh = SurfaceTessellator.Tessellate(SurfaceTessellator_Accuracy.ByName(name), new TessellationOptions(tolerance));
        MeshMeasure.AssertClosed(mesh, euler);
    }

    [Theory]
    [InlineData("sphere")]
    [InlineData("torus")]
    public void No_vertex_lies_inside_an_edge_of_the_welded_mesh(string name)
    {
        var mesh = SurfaceTessellator.Tessellate(SurfaceTessellator_Accuracy.ByName(name), new TessellationOptions(3e-2));
        var used = Enumerable.Range(0, mesh.VertexCount).Where(i => mesh.Welded[i] == i).ToArray();
        var edges = new HashSet<(int, int)>();
        for (var t = 0; t < mesh.TriangleCount; t++)
        {
            for (var k = 0; k < 3; k++)
            {
                int a = mesh.Welded[mesh.Indices[3 * t + k]], b = mesh.Welded[mesh.Indices[3 * t + (k + 1) % 3]];
                edges.Add((Math.Min(a, b), Math.Max(a, b)));
            }
        }

        foreach (var (a, b) in edges)
        {
            TwistablePoint pa = mesh.Positions[a], pb = mesh.Positions[b];
            var length = MeshMeasure.Distance(pa, pb);
            foreach (var c in used)
            {
                if (c == a || c == b)
                {
                    continue;
                }

                var pc = mesh.Positions[c];
                var sum = MeshMeasure.Distance(pa, pc) + MeshMeasure.Distance(pc, pb);
                Assert.True(sum - length > 1e-9 * length, $"vertex {c} lies on edge ({a}, {b})");
            }
        }
    }

    [Fact]
    public void Seam_and_pole_copies_stand_exactly_on_their_welded_vertex()
    {
        var mesh = SurfaceTessellator.Tessellate(new SphereSurface(1), new TessellationOptions(1e-2));
        var copies = 0;
        for (var i = 0; i < mesh.VertexCount; i++)
        {
            var w = mesh.Welded[i];
            if (w == i)
            {
                continue;
            }

            copies++;
            Assert.Equal(mesh.Positions[w], mesh.Positions[i]);
            Assert.Equal(mesh.Normals[w], mesh.Normals[i]);
            var (p, q) = (mesh.Parameters[i], mesh.Parameters[w]);
            Assert.True(p.U == 1 || p.V == 0 || p.V == 1, $"copy {i} at {p} is on no seam or pole");
            Assert.True(q.U == 0 || q.V == p.V || q.V == 0 || q.V == 1);
        }

        Assert.True(copies > 0);
    }

    [Fact]
    public void An_open_surface_keeps_its_boundary_and_welds_nothing()
    {
        var mesh = SurfaceTessellator.Tessellate(HeightSheet.Wavy(), new TessellationOptions(1e-2));
        Assert.All(Enumerable.Range(0, mesh.VertexCount), i => Assert.Equal(i, mesh.Welded[i]));
    }
}
