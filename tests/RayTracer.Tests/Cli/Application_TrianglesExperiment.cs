using RayTracer.Cli;

namespace RayTracer.Tests.Cli;

[Collection(RayTracer.Tests.Geometry.Solvers.TriangleTestCollection.Name)]
public sealed class Application_TrianglesExperiment : CommandLineTest
{
    [Fact]
    public void Quick_run_writes_a_report_with_every_scene_and_test_its_charts_and_images()
    {
        var (code, stdout, stderr) = Run("experiments", "triangles", "--quick", "--width", "24", "--height", "18", "-o", Dir);
        Assert.True(code == 0, stderr);
        var report = File.ReadAllText(Path.Combine(Dir, "triangles.md"));
        Assert.Equal(Path.Combine(Dir, "triangles.md"), stdout.Trim());
        foreach (var scene in new[] { "glass-bunny", "glass-shell", "mirror-column", "bumpy-torus", "bumpy-sphere" })
        {
            foreach (var test in new[] { "moller", "algebraic", "plucker", "plucker-edges" })
                Assert.Contains($"| {test} |", report);
            Assert.Contains($"({scene[..4]}", report.Replace("| ", "(", StringComparison.Ordinal));
            Assert.True(new FileInfo(Path.Combine(Dir, "triangles", scene + ".png")).Length > 0);
        }

        foreach (var chart in new[] { "render-time.png", "nearest-hit-time.png", "plucker-gain.png" })
            Assert.Equal([0x89, (byte)'P', (byte)'N', (byte)'G'], File.ReadAllBytes(Path.Combine(Dir, "triangles", chart))[..4]);
    }

    [Fact]
    public void Render_takes_a_triangle_test_for_a_mesh_and_rejects_an_unknown_one()
    {
        var ply = Path.Combine(Dir, "one.ply");
        File.WriteAllText(ply, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
        var image = Path.Combine(Dir, "one.png");
        var (code, _, stderr) = Run("render", "--mesh", ply, "--triangle-test", "plucker-edges", "-o", image, "--width", "16", "--height", "12", "--spp", "1");
        Assert.True(code == 0, stderr);
        Assert.True(File.Exists(image));

        var bad = Run("render", "--mesh", ply, "--triangle-test", "pluecker", "-o", image);
        Assert.Equal(2, bad.Code);
        Assert.Contains("pluecker", bad.Err);

        var noMesh = Run("render", "spheres", "--triangle-test", "plucker", "-o", image);
        Assert.Equal(2, noMesh.Code);
        Assert.Contains("--triangle-test applies to --mesh only", noMesh.Err);
    }
}
