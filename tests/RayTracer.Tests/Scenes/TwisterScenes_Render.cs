using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry.Parametric;
using RayTracer.Geometry;
using RayTracer.Scenes;
using RayTracer.Viewing;

namespace RayTracer.Tests.Scenes;

public class TwisterScenes_Render
{
    public static readonly TheoryData<string> Names = new()
    {
        "twister-cylinders", "twister-curves", "twister-helixes", "twister-epitrochoids", "twister-roulettes", "twister-surfaces",
    };

    [Theory]
    [MemberData(nameof(Names))]
    public void A_tiny_render_of_the_scene_shows_more_than_background(string name)
    {
        Assert.True(SceneFactory.TryCreate(name, out var scene), $"{name} is not registered");
        var world = scene.Build(new SceneSettings { Width = 32, Height = 24, SamplesPerPixel = 1 });
        var image = new Renderer(new RenderOptions { Seed = 1 }).Render(world);

        var pixels = image.Pixels.ToArray();
        var background = pixels.Count(p => p == world.BackgroundColor);
        Assert.True(background < pixels.Length / 2, $"{name}: {background} of {pixels.Length} pixels are background");
        // Ground and backdrop alone give a handful of shades; shaded curved tubes and surfaces give many.
        var shades = pixels.Select(p => (Math.Round(p.r, 3), Math.Round(p.g, 3), Math.Round(p.b, 3))).Distinct().Count();
        Assert.True(shades > 40, $"{name}: only {shades} distinct colours");
    }

    [Theory]
    [MemberData(nameof(Names))]
    public void The_scene_holds_twister_tubes_or_surfaces_that_the_camera_sees(string name)
    {
        SceneFactory.TryCreate(name, out var scene);
        var world = scene!.Build(new SceneSettings { Width = 32, Height = 24, SamplesPerPixel = 1 });
        var shapes = world.Objects.Where(IsTwisterShape).ToList();
        Assert.NotEmpty(shapes);

        // Without them, the same pixels show only the stage: the shapes cover a real part of the picture.
        var with = new Renderer(new RenderOptions { Seed = 1 }).Render(world).Pixels.ToArray();
        foreach (var shape in shapes)
        {
            world.Objects.Remove(shape);
        }

        var without = new Renderer(new RenderOptions { Seed = 1 }).Render(world).Pixels.ToArray();
        var changed = with.Zip(without).Count(p => Distance(p.First, p.Second) > 0.02);
        Assert.True(changed > with.Length / 20, $"{name}: the shapes change only {changed} of {with.Length} pixels");
    }

    private static bool IsTwisterShape(GeometricObject obj) => obj switch
    {
        CurveTube or TessellatedSurface => true,
        Instance instance => IsTwisterShape(instance.Target),
        RayTracer.Geometry.Compound.CompoundObject compound => compound.Parts.Any(IsTwisterShape),
        _ => false,
    };

    private static double Distance(RGBColor a, RGBColor b) => Math.Abs(a.r - b.r) + Math.Abs(a.g - b.g) + Math.Abs(a.b - b.b);
}
