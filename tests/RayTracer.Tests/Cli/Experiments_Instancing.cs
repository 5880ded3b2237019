using RayTracer.Cli;
using RayTracer.Cli.Experiments;
using RayTracer.Scenes;
using RayTracer.Scenes.Instancing;
using RayTracer.Tracing;
using RayTracer.Viewing;
using RayTracer.Viewing.Imaging;

namespace RayTracer.Tests.Cli;

public sealed class Experiments_Instancing : CommandLineTest
{
    public static TheoryData<int> SceneIndices => [0, 1, 2, 3];

    [Theory]
    [MemberData(nameof(SceneIndices))]
    public void Five_cylinder_methods_render_the_same_image(int index)
    {
        var settings = new SceneSettings { Width = 64, Height = 48, SamplesPerPixel = 1 };
        PixelImage? reference = null;
        foreach (var method in Enum.GetValues<CylinderMethod>())
        {
            var scene = InstancingExperiment.Scenes(method)[index];
            var world = scene.Build(settings);
            var image = new Renderer(new RenderOptions { Threads = 1 }).Render(world).ToImage(world.ViewPlane);
            reference ??= image;
            var (max, over) = InstancingExperiment.Compare(reference, image);
            Assert.True(over == 0, $"{scene.Name} {method}: {over} pixels differ by more than {InstancingExperiment.PixelTolerance}, up to {max}");
        }

        // Not a blank stage: the tubes leave many distinct colours.
        var colours = Enumerable.Range(0, reference!.Width * reference.Height)
            .Select(i => (reference.Data[3 * i], reference.Data[3 * i + 1], reference.Data[3 * i + 2])).Distinct().Count();
        Assert.True(colours > 50, $"only {colours} colours");
    }

    [Fact]
    public void Scenes_hold_the_thesis_tube_counts_and_the_tubes_are_seen()
    {
        var counts = InstancingExperiment.Scenes(CylinderMethod.GauCyl).Select(s => s.Cylinders().Count).ToArray();
        Assert.Equal([3, 333, 772, 1192], counts);
        for (var i = 0; i < counts.Length; i++)
        {
            var counter = new InvocationCounter($"test tubes {i}");
            var scene = InstancingExperiment.Scenes(CylinderMethod.GauCyl, t => new InstancingCountedObject(t, counter))[i];
            var world = scene.Build(new SceneSettings { Width = 32, Height = 24, SamplesPerPixel = 1 });
            new Renderer(new RenderOptions { Threads = 1 }).Render(world);
            Assert.True(counter.Total > 32 * 24 / 10, $"{scene.Name}: only {counter.Total} tube tests");
        }
    }

    [Fact]
    public void Quick_report_writes_the_table_the_charts_and_an_image_per_scene()
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        var code = Application.Run(["experiments", "instancing", "--quick", "-o", Dir, "--width", "32", "--height", "24"], stdout, stderr);
        Assert.True(code == 0, stderr.ToString());
        var report = File.ReadAllText(Path.Combine(Dir, "instancing.md"));
        Assert.Contains("| **Total test invocations** | U-Cyl |", report);
        Assert.Contains("| **Bytes per cylinder** | U-Cyl |", report);
        Assert.Contains("experiments instancing --quick", report);
        foreach (var name in new[] { "time", "memory", "gain", "instancing-blocks", "instancing-helix", "instancing-epitrochoid", "instancing-column" })
        {
            var png = Path.Combine(Dir, "instancing", name + ".png");
            Assert.True(File.Exists(png), png);
            Assert.Contains($"instancing/{name}.png", report);
        }

        var image = ImageFile.ReadPixels(Path.Combine(Dir, "instancing", "instancing-helix.png"));
        Assert.Equal((32, 24), (image.Width, image.Height));
        Assert.Empty(Directory.GetFiles(Dir, "*.tmp*", SearchOption.AllDirectories));
    }

    [Fact]
    public void A_bad_size_is_a_usage_error_and_writes_nothing()
    {
        var stderr = new StringWriter();
        var code = Application.Run(["experiments", "instancing", "-o", Dir, "--width", "0"], new StringWriter(), stderr);
        Assert.Equal(2, code);
        Assert.Contains("--width", stderr.ToString());
        Assert.Empty(Directory.GetFileSystemEntries(Dir));
    }
}
