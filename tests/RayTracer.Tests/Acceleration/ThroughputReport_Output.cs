using RayTracer.Acceleration;
using RayTracer.Geometry.Meshes;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Tests.Acceleration;

public class ThroughputReport_Output
{
    [Fact]
    public void Procedural_mesh_has_at_least_the_requested_triangles_and_is_closed()
    {
        var mesh = ThroughputReport.DisplacedSphere(5000);
        Assert.InRange(mesh.TriangleCount, 5000, 5000 * 1.1);
        // Every edge of a closed mesh is shared by exactly two triangles (pole fans included).
        var edges = new Dictionary<(int, int), int>();
        for (int f = 0; f < mesh.TriangleCount; f++)
        {
            for (int k = 0; k < 3; k++)
            {
                int a = mesh.Indices[3 * f + k], b = mesh.Indices[3 * f + (k + 1) % 3];
                var key = (Math.Min(a, b), Math.Max(a, b));
                edges[key] = edges.GetValueOrDefault(key) + 1;
            }
        }

        Assert.All(edges.Values, c => Assert.Equal(2, c));

        // Outward winding: each face normal points away from the centre.
        for (int f = 0; f < mesh.TriangleCount; f++)
        {
            Point3D a = mesh.Vertices[mesh.Indices[3 * f]], b = mesh.Vertices[mesh.Indices[3 * f + 1]], c = mesh.Vertices[mesh.Indices[3 * f + 2]];
            var n = Vector3D.Cross(b - a, c - a);
            Assert.True(Vector3D.Dot(n, a - Point3D.Origin) > 0, $"face {f} points inward");
        }
    }

    [Fact]
    public void Report_names_every_structure_and_their_hit_counts_agree()
    {
        var output = new StringWriter();
        ThroughputReport.Run(output, 2000, 32, 24, 2);
        string[] lines = output.ToString().Split('\n', StringSplitOptions.RemoveEmptyEntries);
        string[] rows = [.. lines.Where(l => !l.StartsWith(' ') && l.Contains("Mrays/s", StringComparison.Ordinal) && l.Contains(" hits ", StringComparison.Ordinal))];
        bool embree = lines.Any(l => l.StartsWith("Embree rtcIntersect1", StringComparison.Ordinal));
        Assert.Equal(embree ? 5 : 3, rows.Length); // Embree adds rtcIntersect1 and rtcIntersect8
        Assert.Contains(rows, r => r.StartsWith("regular grid", StringComparison.Ordinal));
        Assert.Contains(rows, r => r.StartsWith("BIH", StringComparison.Ordinal));
        Assert.Contains(rows, r => r.StartsWith("SAH BVH", StringComparison.Ordinal));
        string[] hitCounts = [.. rows.Select(r => r[(r.LastIndexOf("hits", StringComparison.Ordinal) + 4)..].Trim())];
        Assert.All(hitCounts, h => Assert.Equal(hitCounts[0], h));
        Assert.NotEqual("0", hitCounts[0]);
        if (!embree)
            Assert.Contains(lines, l => l.StartsWith("Embree", StringComparison.Ordinal) && l.Contains("skipped", StringComparison.Ordinal));
    }

    [EmbreeFact]
    public void With_embree_the_report_ends_with_the_primary_shadow_and_build_ratios()
    {
        var output = new StringWriter();
        ThroughputReport.Run(output, 2000, 32, 24, 1);
        string[] lines = output.ToString().Split('\n', StringSplitOptions.RemoveEmptyEntries);
        int at = Array.FindIndex(lines, l => l.StartsWith("ratios, SAH BVH against Embree", StringComparison.Ordinal));
        Assert.True(at >= 0, output.ToString());
        Assert.Equal(at + 4, lines.Length);
        string[] names = ["primary rays (rtcIntersect1)", "shadow rays (rtcOccluded1)", "build time"];
        for (int k = 0; k < 3; k++)
        {
            string line = lines[at + 1 + k].Trim();
            Assert.StartsWith(names[k], line, StringComparison.Ordinal);
            double ratio = double.Parse(line[names[k].Length..].TrimStart().Split(' ')[0], System.Globalization.CultureInfo.InvariantCulture);
            Assert.True(ratio > 0 && double.IsFinite(ratio), line);
        }
    }

    [Fact]
    public void Shadow_rays_start_at_the_primary_hits_and_are_counted_as_occluded()
    {
        var output = new StringWriter();
        ThroughputReport.Run(output, 2000, 32, 24, 1);
        string[] lines = output.ToString().Split('\n', StringSplitOptions.RemoveEmptyEntries);
        string hits = lines.Single(l => l.StartsWith("SAH BVH ", StringComparison.Ordinal) && l.Contains(" hits ", StringComparison.Ordinal)).Split("hits ")[1].Trim();
        Assert.Contains(lines, l => l.StartsWith($"shadow rays: {hits},", StringComparison.Ordinal));
        string occluded = lines.Single(l => l.StartsWith("SAH BVH any hit", StringComparison.Ordinal)).Split("occluded ")[1].Trim();
        // The light is above and to the side: some of the lit sphere faces away from it, not all.
        int count = int.Parse(occluded, System.Globalization.NumberStyles.AllowThousands, System.Globalization.CultureInfo.InvariantCulture);
        Assert.InRange(count, 1, int.Parse(hits, System.Globalization.NumberStyles.AllowThousands, System.Globalization.CultureInfo.InvariantCulture) - 1);
        Assert.DoesNotContain(lines, l => l.Contains("DIFFER", StringComparison.Ordinal));
    }

    [Fact]
    public void Primary_rays_hit_the_sphere_where_the_camera_sees_it()
    {
        // Brute force over a small mesh: the count of rays hitting it must match the structure's.
        var mesh = ThroughputReport.DisplacedSphere(600);
        var triangles = mesh.CreateTriangles(false);
        var bvh = new Bvh(triangles);
        long viaBvh = ThroughputReport.CastPrimaryRays(bvh, 20, 15, 1);
        long brute = 0;
        double halfHeight = Math.Tan(0.5 * MathConstants.ToRadians(45)), halfWidth = halfHeight * 20 / 15;
        for (int row = 0; row < 15; row++)
        {
            for (int col = 0; col < 20; col++)
            {
                var ray = new Ray(new Point3D(0, 0, 3.2), new Vector3D(halfWidth * (2 * (col + 0.5) / 20 - 1), halfHeight * (1 - 2 * (row + 0.5) / 15), -1));
                brute += triangles.Any(t => t.Intersect(ray, out _)) ? 1 : 0;
            }
        }

        Assert.Equal(brute, viaBvh);
        Assert.True(brute > 50);
    }
}
