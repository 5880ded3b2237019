using Twister.Tessellation;
using Twister.Tests.Tessellation.Shapes;

namespace Twister.Tests.Tessellation;

public class SurfaceTessellator_Accuracy
{
    public static IParametricSurface ByName(string name) => name switch
    {
        "sphere" => new SphereSurface(1),
        "torus" => new TorusSurface(1, 0.35),
        "wavy" => HeightSheet.Wavy(),
        "bump" => HeightSheet.Bump(),
        _ => throw new ArgumentException(name),
    };

    [Theory]
    [InlineData("sphere", 1e-2)]
    [InlineData("sphere", 1e-3)]
    [InlineData("torus", 1e-2)]
    [InlineData("torus", 1e-3)]
    [InlineData("wavy", 1e-3)]
    [InlineData("bump", 1e-3)]
    public void Chord_error_at_random_parameters_inside_triangles_is_within_the_tolerance(string name, double tolerance)
    {
        var surface = ByName(name);
        var mesh = SurfaceTessellator.Tessellate(surface, new TessellationOptions(tolerance));
        Assert.True(mesh.TriangleCount > 32);
        Assert.InRange(MeshMeasure.MaxChordError(surface, mesh), 0, tolerance);
    }

    [Fact]
    public void Vertices_lie_on_the_surface_at_their_parameters()
    {
        var surface = new TorusSurface(1, 0.35);
        var mesh = SurfaceTessellator.Tessellate(surface, new TessellationOptions(1e-2));
        for (var i = 0; i < mesh.VertexCount; i++)
        {
            var p = mesh.Parameters[i];
            Assert.InRange(p.U, 0, 1);
            Assert.InRange(p.V, 0, 1);
            Assert.True(MeshMeasure.Distance(surface.PointAt(p.U, p.V), mesh.Positions[i]) < 1e-12);
        }
    }

    [Fact]
    public void Normals_are_the_unit_outward_normals_also_at_the_poles()
    {
        var mesh = SurfaceTessellator.Tessellate(new SphereSurface(2), new TessellationOptions(1e-2));
        for (var i = 0; i < mesh.VertexCount; i++)
        {
            var n = mesh.Normals[i];
            var p = mesh.Positions[i];
            // On a sphere about the origin the outward unit normal is the position over the radius.
            var angle = Math.Acos(Math.Clamp((n.x * p.x + n.y * p.y + n.z * p.z) / 2, -1, 1));
            Assert.True(angle < 1e-6, $"vertex {i} at {mesh.Parameters[i]}: normal {n} is {angle} rad off");
        }
    }

    [Theory]
    [InlineData("sphere")]
    [InlineData("torus")]
    [InlineData("wavy")]
    public void Triangles_face_the_way_of_the_surface_normal(string name)
    {
        var surface = ByName(name);
        var mesh = SurfaceTessellator.Tessellate(surface, new TessellationOptions(1e-3));
        for (var t = 0; t < mesh.TriangleCount; t++)
        {
            TwistablePoint a = mesh.Positions[mesh.Indices[3 * t]], b = mesh.Positions[mesh.Indices[3 * t + 1]], c = mesh.Positions[mesh.Indices[3 * t + 2]];
            double ex = b.x - a.x, ey = b.y - a.y, ez = b.z - a.z, fx = c.x - a.x, fy = c.y - a.y, fz = c.z - a.z;
            double nx = ey * fz - ez * fy, ny = ez * fx - ex * fz, nz = ex * fy - ey * fx;
            if (Math.Sqrt(nx * nx + ny * ny + nz * nz) < 1e-9 * Math.Sqrt((ex * ex + ey * ey + ez * ez) * (fx * fx + fy * fy + fz * fz)))
            {
                continue; // a sliver with no area has no side to face
            }

            var sum = Enumerable.Range(0, 3).Select(k => mesh.Normals[mesh.Indices[3 * t + k]])
                .Aggregate(0.0, (acc, n) => acc + n.x * nx + n.y * ny + n.z * nz);
            Assert.True(sum > 0, $"triangle {t} at {mesh.Parameters[mesh.Indices[3 * t]]} faces inward");
        }
    }

    [Fact]
    public void The_same_seed_gives_the_same_mesh_and_another_seed_still_meets_the_tolerance()
    {
        var surface = new TorusSurface(1, 0.35);
        var first = SurfaceTessellator.Tessellate(surface, new TessellationOptions(1e-3) { Seed = 3 });
        var again = SurfaceTessellator.Tessellate(surface, new TessellationOptions(1e-3) { Seed = 3 });
        var other = SurfaceTessellator.Tessellate(surface, new TessellationOptions(1e-3) { Seed = 4 });
        Assert.Equal(first.Indices, again.Indices);
        Assert.Equal(first.Parameters, again.Parameters);
        Assert.InRange(MeshMeasure.MaxChordError(surface, other), 0, 1e-3);
    }
}
