using System.Text;

namespace RayTracer.Tests.Cli;

public sealed class Application_Bench : CommandLineTest
{
    /// <summary>A tetrahedron in ASCII PLY.</summary>
    private string WriteTetrahedronPly()
    {
        const string text = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n" +
            "element face 4\nproperty list uchar int vertex_indices\nend_header\n" +
            "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n";
        var path = Path.Combine(Dir, "tetra.ply");
        File.WriteAllText(path, text, Encoding.ASCII);
        return path;
    }

    [Fact]
    public void Measures_a_mesh_file_through_the_studio_camera()
    {
        var mesh = WriteTetrahedronPly();
        var (code, output, error) = Run("bench", "--mesh", mesh, "--width", "12", "--height", "9", "--threads", "1");
        Assert.True(code == 0, error);
        Assert.Contains("4 triangles", output);
        Assert.Contains("108 primary rays", output);
        string[] rows = [.. output.Split('\n').Where(l => l.Contains("Mrays/s", StringComparison.Ordinal))];
        Assert.Contains(rows, r => r.StartsWith("SAH BVH ", StringComparison.Ordinal) && r.Contains("hits", StringComparison.Ordinal));
        Assert.Contains(rows, r => r.StartsWith("SAH BVH any hit", StringComparison.Ordinal) && r.Contains("occluded", StringComparison.Ordinal));
        Assert.Contains("Embree", output); // a row, or the reason it is skipped
        Assert.DoesNotContain("DIFFER", output);
    }

    [Fact]
    public void Takes_the_camera_options_of_render()
    {
        var mesh = WriteTetrahedronPly();
        var (code, output, error) = Run("bench", "--mesh", mesh, "--width", "8", "--height", "6", "--threads", "1",
            "--camera", "fisheye:180", "--eye", "0,0,6", "--look-at", "0,0,0");
        Assert.True(code == 0, error);
        Assert.Contains("through the fisheye:180 camera", output);
    }

    [Fact]
    public void Rejects_a_missing_or_broken_mesh_like_render()
    {
        var (code, _, error) = Run("bench", "--mesh", Path.Combine(Dir, "none.ply"));
        Assert.Equal(2, code);
        Assert.Contains("no such file", error);

        var broken = Path.Combine(Dir, "broken.ply");
        File.WriteAllText(broken, "ply\nformat ascii 1.0\nelement vertex 1\nend_header\n0\n");
        (code, _, error) = Run("bench", "--mesh", broken, "--width", "4", "--height", "3");
        Assert.Equal(1, code);
        Assert.Contains("broken.ply", error);
        Assert.Contains("error", error);
    }

    [Theory]
    [InlineData("--triangles", "100")]
    [InlineData("--eye", "1,2,3")]
    public void Options_of_the_other_mode_are_usage_errors(string option, string value)
    {
        var args = option == "--triangles" ? new[] { "bench", "--mesh", WriteTetrahedronPly(), option, value } : ["bench", option, value];
        var (code, _, error) = Run(args);
        Assert.Equal(2, code);
        Assert.Contains(option, error);
    }

    [Fact]
    public void Camera_problems_found_on_the_scene_are_usage_errors()
    {
        // The studio's look-at point is the mesh's centre, the origin here.
        var (code, _, error) = Run("bench", "--mesh", WriteTetrahedronPly(), "--eye", "0,0,0", "--width", "4", "--height", "3");
        Assert.Equal(2, code);
        Assert.StartsWith("raytracer: error:", error);
    }
}
