using System.Globalization;
using System.Text;
using RayTracer.Cli;
using RayTracer.Geometry.Meshes;
using RayTracer.Maths;
using RayTracer.Scenes.Meshes;
using RayTracer.Viewing;
using RayTracer.Viewing.Imaging;

namespace RayTracer.Tests.Cli;

public sealed class Application_MeshStudio : CommandLineTest
{
    private const int Width = 64, Height = 48;




    /// <summary>A regular tetrahedron away from the origin, in ASCII PLY with one line a strict reader would not know.</summary>
    private static readonly Point3D[] Tetrahedron =
        [new(6, 3, -2), new(6, 1, -4), new(4, 3, -4), new(4, 1, -2)];

    private string WriteTetrahedronPly()
    {
        var text = new StringBuilder("ply\nformat ascii 1.0\nCreated by a modeller\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n");
        text.Append("element face 4\nproperty list uchar int vertex_indices\nend_header\n");
        foreach (var p in Tetrahedron)
            text.Append(CultureInfo.InvariantCulture, $"{p.x} {p.y} {p.z}\n");
        text.Append("3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n");
        var path = Path.Combine(Dir, "tetra.ply");
        File.WriteAllText(path, text.ToString());
        return path;
    }

    [Fact]
    public void Renders_a_mesh_file_with_the_whole_mesh_in_view_on_a_ground()
    {
        var mesh = WriteTetrahedronPly();
        var output = Path.Combine(Dir, "tetra.png");

        var (code, _, err) = Run("render", "--mesh", mesh, "-o", output, "--width", $"{Width}", "--height", $"{Height}", "--spp", "1", "--threads", "1");

        Assert.Equal(0, code);
        Assert.Contains($"{mesh}(3): warning: skipped unknown header line", err);
        var image = ImageFile.ReadPixels(output);
        Assert.Equal((Width, Height), (image.Width, image.Height));

        // The camera as fitted: looking at the centre of the bounding box from the studio's direction.
        var centre = new Point3D(5, 2, -3);
        var camera = (PinholeCamera)new MeshStudioScene(PlyReader.Read(mesh), mesh)
            .Build(new() { Width = Width, Height = Height }).Camera!;
        Assert.Equal(0, camera.LookAt.Distance(centre), 9);
        var w = (camera.Eye - centre).Normalized();
        var u = Vector3D.UnitY.Cross(w).Normalized();
        var v = w.Cross(u);
        var viewDistance = Width / 2.0 / Math.Tan(MathConstants.ToRadians(MeshStudioScene.HorizontalFieldOfViewDegrees) / 2);

        // Every vertex projects inside the image, clear of its edges.
        foreach (var p in Tetrahedron)
        {
            var d = p - camera.Eye;
            var depth = -d.Dot(w);
            var x = d.Dot(u) / depth * viewDistance;
            var y = d.Dot(v) / depth * viewDistance;
            Assert.InRange(Math.Abs(x), 0, 0.9 * Width / 2);
            Assert.InRange(Math.Abs(y), 0, 0.9 * Height / 2);
        }

        var background = Tone(MeshStudioScene.Background);
        Assert.NotEqual(background, image.GetRgb(Width / 2, Height / 2));

        // Each corner shows the ground where its ray meets the plane under the mesh, else the background.
        var groundHeight = Tetrahedron.Min(p => p.y);
        foreach (var (column, row) in new[] { (0, 0), (Width - 1, 0), (0, Height - 1), (Width - 1, Height - 1) })
        {
            var direction = (column + 0.5 - Width / 2.0) * u + (Height / 2.0 - row - 0.5) * v - viewDistance * w;
            var hitsGround = direction.y < 0 && camera.Eye.y > groundHeight;
            if (hitsGround)
                Assert.NotEqual(background, image.GetRgb(column, row));
            else
                Assert.Equal(background, image.GetRgb(column, row));
        }
    }

    [Fact]
    public void A_malformed_mesh_is_reported_at_its_line_and_nothing_is_written()
    {
        var mesh = Path.Combine(Dir, "broken.ply");
        File.WriteAllText(mesh, "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 zero 0\n");
        var output = Path.Combine(Dir, "never.png");

        var (code, _, err) = Run("render", "--mesh", mesh, "-o", output);

        Assert.Equal(1, code);
        Assert.StartsWith($"{mesh}(8", err);
        Assert.Contains(": error: ", err);
        Assert.False(File.Exists(output));
    }

    [Fact]
    public void A_mesh_with_a_scene_name_is_a_usage_error()
    {
        var mesh = WriteTetrahedronPly();
        var (code, _, err) = Run("render", "spheres", "--mesh", mesh, "-o", Path.Combine(Dir, "x.png"));
        Assert.Equal(2, code);
        Assert.Contains("--mesh", err);
        Assert.Contains("'spheres'", err);
    }

    private static (byte, byte, byte) Tone(Colors.RGBColor c) =>
        (FrameBuffer.ToByte(c.r, 2.2), FrameBuffer.ToByte(c.g, 2.2), FrameBuffer.ToByte(c.b, 2.2));
}
