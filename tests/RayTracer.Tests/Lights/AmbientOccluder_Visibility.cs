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

namespace RayTracer.Tests.Lights;

public class AmbientOccluder_Visibility
{
    private static double Render(bool withCeiling, int samples)
    {
        var world = TestScenes.OrthographicWorld(1, 0.01, w => new RayCastIntegrator(w), samples);
        var camera = new OrthographicCamera { Eye = new Point3D(0, 0, 0.5), LookAt = Point3D.Origin };
        camera.ComputeUVW();
        world.Camera = camera;
        world.AmbientLight = new AmbientOccluder(new MultiJitteredSampler(samples), 2.0, null, 0.25);
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 0, 1)) { Material = new Matte(0.5, 0, RGBColor.White) });
        if (withCeiling)
            world.Add(new Plane(new Point3D(0, 0, 1), new Normal3D(0, 0, -1)) { Material = new Matte(), CastsShadows = true });
        return new Renderer(new RenderOptions { Seed = 2 }).Render(world)[0, 0].r;
    }

    [Fact]
    public void Open_sky_gives_full_light_and_a_ceiling_gives_the_minimum()
    {
        Assert.Equal(0.5 * 2.0, Render(false, 16), 12);
        Assert.Equal(0.5 * 2.0 * 0.25, Render(true, 16), 12);
    }

    [Fact]
    public void Half_the_cosine_weighted_hemisphere_blocked_gives_the_average()
    {
        // A wall plane through the shading point's neighbourhood blocking x > 0 removes half of the
        // cosine-distributed directions, so the expected light is the mean of the two levels.
        var world = TestScenes.OrthographicWorld(1, 0.001, w => new RayCastIntegrator(w), 256);
        var camera = new OrthographicCamera { Eye = new Point3D(0, 0, 0.5), LookAt = Point3D.Origin };
        camera.ComputeUVW();
        world.Camera = camera;
        world.AmbientLight = new AmbientOccluder(new MultiJitteredSampler(256), 1.0, null, 0.0);
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 0, 1)) { Material = new Matte(1, 0, RGBColor.White) });
        world.Add(new Plane(new Point3D(1e-4, 0, 0), new Normal3D(-1, 0, 0)) { Material = new Matte() });
        var value = new Renderer(new RenderOptions { Seed = 4 }).Render(world)[0, 0].r;
        Assert.InRange(value, 0.45, 0.55);
    }
}
