using RayTracer.Cli;

namespace RayTracer.Tests.Cli;

public sealed class Application_Help : CommandLineTest
{
    [Theory]
    [InlineData(new[] { "--help" }, new[] { "list", "render", "bench" })]
    [InlineData(new[] { "-h" }, new[] { "list", "render", "bench" })]
    [InlineData(new[] { "list", "--help" }, new string[0])]
    [InlineData(new[] { "render", "--help" }, new[] { "--output", "-o", "--width", "--height", "--spp", "--samples", "--seed", "--threads", "--max-depth", "--image", "--mesh", "SCENE" })]
    [InlineData(new[] { "bench", "--help" }, new[] { "--triangles", "--width", "--height", "--threads" })]
    [InlineData(new[] { "help", "render" }, new[] { "--output", "--mesh" })]
    public void Help_exits_0_and_lists_the_command_options(string[] args, string[] expected)
    {
        var (code, output, err) = Run(args);
        Assert.Equal(0, code);
        Assert.Equal("", err);
        Assert.Contains("Usage:", output);
        Assert.Contains("--help", output);
        foreach (var name in expected)
            Assert.Contains(name, output);
    }

    [Fact]
    public void A_misspelt_option_exits_2_naming_it_and_suggesting_the_right_one()
    {
        var output = Path.Combine(Dir, "x.png");
        var (code, _, err) = Run("render", "spheres", "-o", output, "--sampels", "4");
        Assert.Equal(2, code);
        Assert.StartsWith("raytracer: error:", err);
        Assert.Contains("'--sampels'", err);
        Assert.Contains("--samples", err.Replace("'--sampels'", ""));
        Assert.False(File.Exists(output));
    }

    [Theory]
    [InlineData("--samples=4", "--width=6")]
    [InlineData("--samples", "4", "--width", "6")]
    [InlineData("-s", "4", "--width=6")]
    [InlineData("--spp=4", "--width", "6")]
    public void Options_take_their_value_after_a_space_or_an_equals_sign(params string[] options)
    {
        var output = Path.Combine(Dir, "eq.png");
        var (code, _, err) = Run(["render", "spheres", "-o", output, "--height", "4", "--threads", "1", .. options]);
        Assert.Equal(0, code);
        Assert.Contains("6x4, 4 spp", err);
    }

    [Fact]
    public void Out_of_range_values_name_the_option_and_the_limits()
    {
        var (code, _, err) = Run("render", "-o", Path.Combine(Dir, "x.png"), "--threads", "0");
        Assert.Equal(2, code);
        Assert.Contains("--threads must be between 1 and 1024, got 0", err);
    }

    [Fact]
    public void An_unsupported_output_extension_names_it_and_the_accepted_ones()
    {
        var (code, _, err) = Run("render", "-o", Path.Combine(Dir, "x.tiff"));
        Assert.Equal(2, code);
        Assert.Contains("'.tiff'", err);
        Assert.Contains(".png, .hdr", err);
    }
}
