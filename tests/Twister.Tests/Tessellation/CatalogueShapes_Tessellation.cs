using Twister.Tessellation;

namespace Twister.Tests.Tessellation;

/// <summary>The catalogue's own twist-built shapes (not closed-form stand-ins) through the tessellators.</summary>
public class CatalogueShapes_Tessellation
{
    private static readonly TwistablePoint Centre = new(0.3, -0.2, 0.5);
    private const double SphereRadius = 1.2, MajorRadius = 1, MinorRadius = 0.35;

    public static TheoryData<string, int> ClosedShapes => new() { { "sphere", 2 }, { "torus", 0 } };

    private static IParametricSurface Surface(string name) => name switch
    {
        "sphere" => TwistSurfaces.Sphere(Centre, SphereRadius),
        "torus" => TwistSurfaces.Torus(MajorRadius, MinorRadius),
        "seashell" => TwistSurfaces.Seashell(1, 0.4, 3, 2, -0.5),
        _ => throw new ArgumentException(name),
    };

    /// <summary>A direction from the solid's core to <paramref name="p"/>: from the sphere's centre, or from the nearest point of the torus's core circle.</summary>
    private static (double X, double Y, double Z) Outward(string name, TwistablePoint p)
    {
        if (name == "sphere")
        {
            return (p.x - Centre.x, p.y - Centre.y, p.z - Centre.z);
        }

        var rho = Math.Sqrt(p.x * p.x + p.y * p.y);
        return (p.x - MajorRadius * p.x / rho, p.y - MajorRadius * p.y / rho, p.z);
    }

    [Theory]
    [MemberData(nameof(ClosedShapes))]
    public void A_closed_catalogue_surface_welds_into_a_closed_mesh_of_its_euler_characteristic(string name, int euler)
    {
        var mesh = SurfaceTessellator.Tessellate(Surface(name), new TessellationOptions(5e-3));
        MeshMeasure.AssertClosed(mesh, euler);
    }

    [Theory]
    [InlineData("sphere")]
    [InlineData("torus")]
    public void Vertex_normals_and_triangles_of_a_closed_catalogue_surface_face_outward(string name)
    {
        var mesh = SurfaceTessellator.Tessellate(Surface(name), new TessellationOptions(5e-3));
        for (var i = 0; i < mesh.VertexCount; i++)
        {
            var (x, y, z) = Outward(name, mesh.Positions[i]);
            var n = mesh.Normals[i];
            var cosine = (n.x * x + n.y * y + n.z * z) / Math.Sqrt(x * x + y * y + z * z);
            Assert.True(Math.Abs(Math.Sqrt(n.x * n.x + n.y * n.y + n.z * n.z) - 1) < 1e-9, $"normal {i} is not unit");
            Assert.True(cosine > 0.999, $"vertex {i} at {mesh.Parameters[i]}: normal {n} is not outward (cos {cosine})");
        }

        var inward = 0;
        for (var t = 0; t < mesh.TriangleCount; t++)
        {
            TwistablePoint a = mesh.Positions[mesh.Indices[3 * t]], b = mesh.Positions[mesh.Indices[3 * t + 1]], c = mesh.Positions[mesh.Indices[3 * t + 2]];
            double ex = b.x - a.x, ey = b.y - a.y, ez = b.z - a.z, fx = c.x - a.x, fy = c.y - a.y, fz = c.z - a.z;
            double nx = ey * fz - ez * fy, ny = ez * fx - ex * fz, nz = ex * fy - ey * fx;
            var (ox, oy, oz) = Outward(name, new((a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3));
            if (nx * ox + ny * oy + nz * oz < 0)
            {
                inward++;
            }
        }

        Assert.Equal(0, inward);
    }

    [Theory]
    [InlineData("sphere", 2e-3)]
    [InlineData("torus", 2e-3)]
    [InlineData("seashell", 2e-3)]
    public void Chord_error_at_random_parameters_inside_triangles_is_within_the_tolerance(string name, double tolerance)
    {
        var surface = Surface(name);
        var mesh = SurfaceTessellator.Tessellate(surface, new TessellationOptions(tolerance));
        Assert.True(mesh.TriangleCount > 100);
        Assert.InRange(MeshMeasure.MaxChordError(surface, mesh), 0, tolerance);
    }

    [Theory]
    [InlineData("epitrochoid", 1e-3)]
    [InlineData("rose", 1e-3)]
    [InlineData("helix", 1e-3)]
    [InlineData("conical-helix", 1e-4)]
    public void Curve_samples_of_a_catalogue_curve_stay_within_the_tolerance(string name, double tolerance)
    {
        IParametricCurve curve = name switch
        {
            "epitrochoid" => TwistCurves.Epitrochoid(5, 3, 2.5, 3),
            "rose" => TwistCurves.Rose(1.5, 4.0 / 3, 3),
            "helix" => TwistCurves.Helix(0.5, 6, 2),
            "conical-helix" => TwistCurves.ConicalHelix(0.7, 0, 8, 1.8),
            _ => throw new ArgumentException(name),
        };
        var line = CurveSampler.Sample(curve, new TessellationOptions(tolerance));
        Assert.True(line.SegmentCount > 16);

        var random = new Random(17);
        var worst = 0.0;
        for (var k = 0; k < line.SegmentCount; k++)
        {
            double t0 = line.Parameters[k], t1 = line.Parameters[k + 1];
            TwistablePoint p0 = line.Points[k], p1 = line.Points[k + 1];
            for (var i = 0; i < 32; i++)
            {
                var s = random.NextDouble();
                var chord = new TwistablePoint(p0.x + s * (p1.x - p0.x), p0.y + s * (p1.y - p0.y), p0.z + s * (p1.z - p0.z));
                worst = Math.Max(worst, MeshMeasure.Distance(curve.PointAt(t0 + s * (t1 - t0)), chord));
            }
        }

        Assert.InRange(worst, 0, tolerance);
    }
}
