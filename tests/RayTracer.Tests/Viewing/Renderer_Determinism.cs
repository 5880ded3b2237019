using RayTracer.Colors;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Sampling;
using RayTracer.Tests.Tracing;
using RayTracer.Tracing;
using RayTracer.Viewing;
using RayTracer.Viewing.Imaging;

namespace RayTracer.Tests.Viewing;

public class Renderer_Determinism
{
    private static byte[] Render(int threads, ulong seed, int tileSize = 4)
    {
        var world = TestScenes.OrthographicWorld(24, 0.12, w => new PathIntegrator(w), samples: 4);
        world.ViewPlane.MaxDepth = 4;
        world.Environment = new EnvironmentLight(new MultiJitteredSampler(4), 1.0);
        world.Add(new Sphere(Point3D.Origin, 1) { Material = new Matte(0, 0.7, new RGBColor(0.9, 0.6, 0.3)) });
        world.Add(new Plane(new Point3D(0, 0, -1), new Normal3D(0, 0.3, 1)) { Material = new Matte(0, 0.5, RGBColor.White) });
        var image = new Renderer(new RenderOptions { Threads = threads, Seed = seed, TileSize = tileSize }).Render(world);
        return image.ToImage(GamutMapping.Clamp, 2.2).Data;
    }

    [Fact]
    public void Image_depends_on_the_seed_but_not_on_the_thread_count()
    {
        var one = Render(1, 7);
        Assert.Equal(one, Render(2, 7));
        Assert.Equal(one, Render(3, 7, tileSize: 5));
        Assert.NotEqual(one, Render(2, 8));
    }

    [Fact]
    public void Statistics_count_primary_and_secondary_rays()
    {
        var world = TestScenes.OrthographicWorld(4, 1, w => new RayCastIntegrator(w), samples: 4);
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 0, 1)) { Material = new Matte() });
        world.Add(new PointLight(new Point3D(0, 0, 5)));
        var result = new Renderer().RenderWithStatistics(world);
        Assert.Equal(4 * 4 * 4, result.PrimaryRays);
        Assert.Equal(2 * 4 * 4 * 4, result.TotalRays); // one shadow ray per primary hit
    }

    [Fact]
    public void Gamut_mapping_and_gamma_follow_their_definitions()
    {
        var c = new RGBColor(2, 1, 0.5);
        Assert.Equal(new RGBColor(1, 1, 0.5), FrameBuffer.MapToGamut(c, GamutMapping.Clamp));
        Assert.Equal(new RGBColor(1, 0.5, 0.25), FrameBuffer.MapToGamut(c, GamutMapping.MaxToOne));
        Assert.Equal((byte)Math.Round(255 * Math.Pow(0.25, 1 / 2.2)), FrameBuffer.ToByte(0.25, 2.2));
        Assert.Equal(0, FrameBuffer.ToByte(double.NaN, 1));
        Assert.Equal(255, FrameBuffer.ToByte(7, 1));
    }
}
