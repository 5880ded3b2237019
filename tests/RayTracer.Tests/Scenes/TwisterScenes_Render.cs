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
    public void A_tiny_render_shows_the_twister_shapes_over_more_than_background(string name)
    {
        Assert.True(SceneFactory.TryCreate(name, out var scene), $"{name} is not registered");
        var world = scene.Build(new SceneSettings { Width = 32, Height = 24, SamplesPerPixel = 1 });
        var with = new Renderer(new RenderOptions { Seed = 1 }).Render(world).Pixels.ToArray();

        var background = with.Count(p => p == world.BackgroundColor);
        Assert.True(background < with.Length / 2, $"{name}: {background} of {with.Length} pixels are background");
        // Ground and backdrop alone give a handful of shades; shaded curved tubes and surfaces give many.
        var shades = with.Select(p => (Math.Round(p.r, 3), Math.Round(p.g, 3), Math.Round(p.b, 3))).Distinct().Count();
        Assert.True(shades > 40, $"{name}: only {shades} distinct colours");

        // Without the tubes and tessellated surfaces the same pixels show only the stage: the shapes cover a real part of the picture.
        var shapes = world.Objects.Where(IsTwisterShape).ToList();
        Assert.NotEmpty(shapes);
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
