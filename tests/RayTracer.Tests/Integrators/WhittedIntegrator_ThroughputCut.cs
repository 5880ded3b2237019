using RayTracer.Colors;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tests.Tracing;
using RayTracer.Tracing;
using RayTracer.Viewing;

namespace RayTracer.Tests.Integrators;

public class WhittedIntegrator_ThroughputCut
{
    private static RenderResult Render(int maxDepth, double minimumThroughput) =>
        new Renderer(new RenderOptions { Threads = 2 }).RenderWithStatistics(GlassScene.Build(maxDepth, minimumThroughput));

    [Fact]
    public void Facing_mirrors_stop_once_the_product_of_reflectances_falls_below_the_threshold()
    {
        // The ray at depth k has throughput kr^k; with kr = 0.5 and a threshold of 0.1 depths 0..3 are
        // traced (0.5^3 = 0.125) and depth 4 (0.0625) is not, although the depth limit is far away.
        const double ka = 0.3, kr = 0.5;
        var world = TestScenes.OrthographicWorld(1, 0.01, w => new WhittedIntegrator(w));
        world.ViewPlane.MaxDepth = 50;
        world.ViewPlane.MinimumThroughput = 0.1;
        var camera = new OrthographicCamera { Eye = new Point3D(0, 0, 1), LookAt = Point3D.Origin };
        camera.ComputeUVW();
        world.Camera = camera;
        world.AmbientLight = new AmbientLight(1.0);
        var mirror = new Reflective(ka, 0, RGBColor.White, 0, 10, kr, RGBColor.White);
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 0, 1)) { Material = mirror });
        world.Add(new Plane(new Point3D(0, 0, 2), new Normal3D(0, 0, -1)) { Material = mirror });

        var result = new Renderer().RenderWithStatistics(world);

        Assert.Equal(ka * (1 - Math.Pow(kr, 4)) / (1 - kr), result.Image[0, 0].r, 12);
        Assert.Equal(4, result.TotalRays);
    }

    [Fact]
    public void Glass_stops_spawning_rays_long_before_a_huge_maximum_depth()
    {
        // Every dielectric hit splits a ray in two; without the throughput cut the ray count grows
        // exponentially with the depth limit. With it, the tree is complete before the limit matters.
        var atLimit = Render(ViewPlane.DeepestMaxDepth, ViewPlane.DefaultMinimumThroughput);
        var huge = Render(400, ViewPlane.DefaultMinimumThroughput);

        Assert.Equal(atLimit.TotalRays, huge.TotalRays);
        Assert.Equal(atLimit.Image.Pixels.ToArray(), huge.Image.Pixels.ToArray());
    }

    [Fact]
    public void The_cut_changes_an_ordinary_render_by_less_than_one_part_in_255()
    {
        var full = Render(8, 0);
        var cut = Render(8, ViewPlane.DefaultMinimumThroughput);

        Assert.True(cut.TotalRays < full.TotalRays, "the scene should exercise the cut");
        for (var i = 0; i < full.Image.Pixels.Length; i++)
        {
            RGBColor reference = full.Image.Pixels[i], actual = cut.Image.Pixels[i];
            Assert.InRange(reference.r - actual.r, -reference.r / 255, reference.r / 255);
            Assert.InRange(reference.g - actual.g, -reference.g / 255, reference.g / 255);
            Assert.InRange(reference.b - actual.b, -reference.b / 255, reference.b / 255);
        }
    }
}
