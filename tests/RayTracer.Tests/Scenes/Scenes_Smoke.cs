using RayTracer.Factories;
using RayTracer.Scenes;
using RayTracer.Viewing;

namespace RayTracer.Tests.Scenes;

public class Scenes_Smoke
{
    public static TheoryData<string> SceneNames()
    {
        var data = new TheoryData<string>();
        foreach (var name in SceneFactory.Names)
            data.Add(name);
        return data;
    }

    [Theory]
    [MemberData(nameof(SceneNames))]
    public void Every_scene_renders_a_tiny_image_without_nan_and_not_all_black(string name)
    {
        Assert.True(SceneFactory.TryCreate(name, out var scene));
        var world = scene.Build(new SceneSettings { Width = 12, Height = 9, SamplesPerPixel = 2, MaxDepth = 3 });
        var image = new Renderer(new RenderOptions { Seed = 1 }).Render(world);
        Assert.Equal(world.Camera!.ImageWidth(world.ViewPlane), image.Width);
        var lit = 0;
        foreach (var p in image.Pixels)
        {
            Assert.False(double.IsNaN(p.r) || double.IsNaN(p.g) || double.IsNaN(p.b), $"NaN pixel in {name}");
            Assert.True(p.r >= 0 && p.g >= 0 && p.b >= 0, $"negative radiance in {name}");
            if (p.r + p.g + p.b > 1e-3) lit++;
        }
        // Pure path tracing at 2 spp finds the small ceiling light on only a few paths.
        var expected = name == "path-tracing" ? 3 : image.Width * image.Height / 4;
        Assert.True(lit >= expected, $"{name}: only {lit} lit pixels");
    }

    [Fact]
    public void Scene_names_are_unique_and_the_default_exists()
    {
        var names = SceneFactory.Names.ToList();
        Assert.Equal(names.Count, names.Distinct(StringComparer.OrdinalIgnoreCase).Count());
        Assert.Contains(SceneFactory.DefaultSceneName, names);
        Assert.False(SceneFactory.TryCreate("no-such-scene", out _));
        Assert.True(SceneFactory.TryCreate("SPHERES", out _));
    }

    [Fact]
    public void Settings_override_the_scene_defaults()
    {
        SceneFactory.TryCreate("spheres", out var scene);
        var world = scene!.Build(new SceneSettings { Width = 33, Height = 21, SamplesPerPixel = 9, MaxDepth = 2 });
        Assert.Equal(33, world.ViewPlane.HorizontalResolution);
        Assert.Equal(21, world.ViewPlane.VerticalResolution);
        Assert.Equal(9, world.ViewPlane.NumSamples);
        Assert.Equal(2, world.ViewPlane.MaxDepth);
    }
}
