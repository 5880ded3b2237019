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

namespace RayTracer.Tests.Integrators;

public class PathIntegrator_Furnace
{
    [Fact]
    public void White_objects_in_a_uniform_environment_have_the_environment_radiance()
    {
        // With albedo 1 everywhere and uniform incident radiance Le, the rendering equation's solution is Le
        // at every point and in every direction, however the objects shadow each other.
        const double le = 0.7;
        var world = TestScenes.OrthographicWorld(8, 0.4, w => new PathIntegrator(w), samples: 16);
        world.ViewPlane.MaxDepth = 40;
        world.Environment = new EnvironmentLight(new MultiJitteredSampler(16), le);
        world.Add(new Sphere(new Point3D(0, 0, 0), 1) { Material = new Matte(0, 1, RGBColor.White) });
        world.Add(new Sphere(new Point3D(1.2, 0.5, -0.8), 0.8) { Material = new Matte(0, 1, RGBColor.White) });
        world.Add(new Plane(new Point3D(0, 0, -1.5), new Normal3D(0, 0, 1)) { Material = new Matte(0, 1, RGBColor.White) });

        var image = new Renderer(new RenderOptions { Seed = 3 }).Render(world);
        foreach (var pixel in image.Pixels.ToArray())
        {
            Assert.Equal(le, pixel.r, 2);
            Assert.Equal(le, pixel.b, 2);
        }
    }

    [Fact]
    public void Grey_sphere_reflects_its_albedo_times_the_environment()
    {
        // A convex object sees only the environment: one bounce gives kd·Le, with area-light sampling too.
        const double le = 2.0, kd = 0.6;
        foreach (var useAreaLighting in new[] { false, true })
        {
            var world = TestScenes.OrthographicWorld(5, 0.5, w => useAreaLighting ? new AreaLightingIntegrator(w) : new PathIntegrator(w), samples: 64);
            var environment = new EnvironmentLight(new MultiJitteredSampler(64), le);
            world.Environment = environment;
            if (useAreaLighting)
                world.Add(environment);
            world.Add(new Sphere(Point3D.Origin, 1) { Material = new Matte(0, kd, RGBColor.White) });
            var image = new Renderer().Render(world);
            Assert.Equal(kd * le, image[2, 2].g, 6);
            Assert.Equal(le, image[0, 0].g, 12); // corner misses the sphere and sees the environment
        }
    }
}
