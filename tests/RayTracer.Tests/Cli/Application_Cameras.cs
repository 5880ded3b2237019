using RayTracer.Cli;
using RayTracer.Factories;

namespace RayTracer.Tests.Cli;

public sealed class Application_Cameras : CommandLineTest
{
    private string[] Render(string scene, params string[] more) =>
        ["render", scene, "-o", Path.Combine(Dir, "out.png"), "--width", "12", "--height", "8", "--spp", "1", "--threads", "2", .. more];

    [Fact]
    public void List_shows_every_camera_of_the_catalogue()
    {
        var (code, output, _) = Run("list");
        Assert.Equal(0, code);
        foreach (var camera in CameraCatalog.All)
            Assert.Contains(camera.Name, output);
        Assert.Contains("gpcm-conic", output);
    }

    [Theory]
    [InlineData("spheres", "cylindrical:180")]
    [InlineData("gpcm-rectangular", "conic:90")]
    [InlineData("camera-stereo", "fisheye")]
    public void Any_scene_renders_behind_any_camera(string scene, string camera)
    {
        var (code, _, err) = Run(Render(scene, "--camera", camera));
        Assert.True(code == 0, err);
        Assert.True(File.Exists(Path.Combine(Dir, "out.png")));
    }

    [Fact]
    public void Eye_look_at_and_up_move_the_scenes_own_camera()
    {
        var (code, _, err) = Run(Render("spheres", "--eye", "0,8,0.5", "--look-at", "0,0,0", "--up", "0,0,-1"));
        Assert.True(code == 0, err);
    }

    [Theory]
    [InlineData("unknown camera 'lens'", "--camera", "lens")]
    [InlineData("less than 180°", "--camera", "rectangular:200")]
    [InlineData("not a number", "--camera", "spherical:x")]
    [InlineData("must be distinct", "--eye", "1,2,3", "--look-at", "1,2,3")]
    [InlineData("zero vector", "--up", "0,0,0")]
    [InlineData("three finite numbers", "--eye", "1,2")]
    [InlineData("three finite numbers", "--look-at", "1,2,inf")]
    public void Bad_camera_options_are_usage_errors_with_a_message(string message, params string[] options)
    {
        var output = Path.Combine(Dir, "out.png");
        var (code, _, err) = Run(Render("spheres", options));
        Assert.Equal(2, code);
        Assert.Contains(message, err);
        Assert.False(File.Exists(output));
    }

    [Fact]
    public void Eye_on_the_scenes_own_look_at_point_is_a_usage_error()
    {
        // The spheres scene looks at (0, 0.9, 0): only the scene knows, so the check comes after building it.
        var (code, _, err) = Run(Render("spheres", "--eye", "0,0.9,0"));
        Assert.Equal(2, code);
        Assert.Contains("distinct", err);
        Assert.False(File.Exists(Path.Combine(Dir, "out.png")));
    }
}
