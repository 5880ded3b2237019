using RayTracer.Cli;
using RayTracer.Viewing.Imaging;

namespace RayTracer.Tests.Cli;

public sealed class Application_Commands : CommandLineTest
{
    [Fact]
    public void List_shows_every_scene_with_a_description()
    {
        var (code, output, _) = Run("list");
        Assert.Equal(0, code);
        Assert.Contains("spheres", output);
        Assert.Contains("path-tracing", output);
        Assert.Contains("camera-stereo", output);
    }

    [Fact]
    public void Render_writes_a_png_of_the_requested_size_and_a_summary()
    {
        var path = Path.Combine(Dir, "out.png");
        var (code, _, err) = Run("render", "spheres", "-o", path, "--width", "16", "--height", "10", "--spp", "1", "--threads", "2");
        Assert.Equal(0, code);
        var image = ImageFile.ReadPixels(path);
        Assert.Equal(16, image.Width);
        Assert.Equal(10, image.Height);
        Assert.Contains("Mrays/s", err);
        Assert.Contains("100%", err);
    }

    [Fact]
    public void Render_output_depends_on_the_seed_only()
    {
        string Render(string name, string threads, string seed)
        {
            var path = Path.Combine(Dir, name);
            Assert.Equal(0, Run("render", "light-area-disk", "-o", path, "--width", "12", "--height", "8", "--spp", "2", "--seed", seed, "--threads", threads).Code);
            return Convert.ToBase64String(File.ReadAllBytes(path));
        }
        var one = Render("a.png", "1", "5");
        Assert.Equal(one, Render("b.png", "2", "5"));
        Assert.NotEqual(one, Render("c.png", "2", "6"));
    }

    [Theory]
    [InlineData("render", "no-such-scene", "-o", "x.png")]
    [InlineData("render", "spheres")]
    [InlineData("render", "spheres", "-o", "x.jpg")]
    [InlineData("render", "spheres", "-o", "x.png", "--width", "0")]
    [InlineData("render", "spheres", "-o", "x.png", "--spp", "many")]
    [InlineData("render", "spheres", "-o", "x.png", "--bogus", "1")]
    [InlineData("render", "spheres", "-o", "x.png", "--width")]
    [InlineData("render", "spheres", "-o", "x.png", "--width", "5", "--width", "6")]
    [InlineData("render", "spheres", "extra", "-o", "x.png")]
    [InlineData("paint")]
    [InlineData]
    [InlineData("list", "extra")]
    [InlineData("bench", "--triangles", "3")]
    [InlineData("render", "spheres", "-o", "x.gif")]
    [InlineData("render", "--samples", "0", "-o", "x.png")]
    [InlineData("render", "--image", "missing.png", "texture-image", "-o", "x.png")]
    [InlineData("render", "spheres", "--mesh", "missing.ply", "-o", "x.png")]
    public void Bad_arguments_exit_with_2_a_message_and_no_output_file(params string[] args)
    {
        var cwd = Environment.CurrentDirectory;
        var resolved = args.Select(a => Path.HasExtension(a) ? Path.Combine(Dir, a) : a).ToArray();
        var (code, _, err) = Run(resolved);
        Assert.Equal(2, code);
        Assert.StartsWith("raytracer: error:", err);
        Assert.Empty(Directory.GetFiles(Dir));
        Assert.Equal(cwd, Environment.CurrentDirectory);
    }

    [Fact]
    public void Image_option_maps_a_png_and_reports_a_bad_one_by_name()
    {
        var texture = Path.Combine(Dir, "texture.png");
        var image = new PixelImage(4, 2, 3);
        Array.Fill(image.Data, (byte)200);
        ImageFile.SavePng(image, texture);
        var good = Path.Combine(Dir, "good.png");
        Assert.Equal(0, Run("render", "texture-image", "-o", good, "--width", "8", "--height", "6", "--spp", "1", "--image", texture).Code);
        Assert.True(File.Exists(good));

        var broken = Path.Combine(Dir, "broken.png");
        File.WriteAllBytes(broken, File.ReadAllBytes(texture)[..30]);
        var output = Path.Combine(Dir, "never.png");
        var (code, _, err) = Run("render", "texture-image", "-o", output, "--width", "8", "--height", "6", "--image", broken);
        Assert.Equal(1, code);
        Assert.Contains(broken, err);
        Assert.False(File.Exists(output));

        Assert.Equal(2, Run("render", "spheres", "-o", output, "--image", texture).Code);
        Assert.False(File.Exists(output));
    }

    [Fact]
    public void Unwritable_output_is_a_failure_not_a_crash()
    {
        var blocker = Path.Combine(Dir, "file");
        File.WriteAllText(blocker, "");
        var (code, _, err) = Run("render", "spheres", "-o", Path.Combine(blocker, "out.png"), "--width", "4", "--height", "4", "--spp", "1");
        Assert.Equal(1, code);
        Assert.Contains("cannot write", err);
    }

    [Fact]
    public void Absurd_max_depth_is_a_usage_error_naming_the_limit()
    {
        var output = Path.Combine(Dir, "deep.png");
        var (code, _, err) = Run("render", "spheres", "-o", output, "--max-depth", "400", "--width", "2", "--height", "2", "--spp", "1");
        Assert.Equal(2, code);
        Assert.Contains("--max-depth must be between 0 and 100, got 400", err);
        Assert.False(File.Exists(output));

        Assert.Equal(0, Run("render", "material-dielectric", "-o", output, "--max-depth", "100", "--width", "8", "--height", "6", "--spp", "1").Code);
        Assert.True(File.Exists(output));
    }

    [Fact]
    public void Render_never_touches_a_user_file_named_like_a_temporary()
    {
        var folder = Path.Combine(Dir, "out");
        Directory.CreateDirectory(folder);
        var output = Path.Combine(folder, "keep.png");
        File.WriteAllText(output + ".tmp", "notes");

        Assert.Equal(0, Run("render", "spheres", "-o", output, "--width", "4", "--height", "4", "--spp", "1").Code);

        Assert.Equal("notes", File.ReadAllText(output + ".tmp"));
        Assert.Equal(4, ImageFile.ReadPixels(output).Width);
        Assert.Equal(2, Directory.GetFiles(folder).Length);
    }

    [Fact]
    public void Bench_reports_every_acceleration_structure()
    {
        var (code, output, _) = Run("bench", "--triangles", "200", "--width", "8", "--height", "6", "--threads", "1");
        Assert.Equal(0, code);
        Assert.Contains("BVH", output);
        Assert.Contains("Mrays/s", output);
    }

    [Fact]
    public void Progress_bar_estimates_the_remaining_time()
    {
        var text = ProgressBar.Render(25, 100, TimeSpan.FromSeconds(10), 20);
        Assert.Contains("25%", text);
        Assert.Contains("ETA 00:30", text);
        Assert.StartsWith("[#####...............]", text);
    }
}
