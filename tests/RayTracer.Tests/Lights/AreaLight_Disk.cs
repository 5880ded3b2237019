using RayTracer.Colors;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tests.Tracing;
using RayTracer.Tracing;
using RayTracer.Viewing;

namespace RayTracer.Tests.Lights;

public class AreaLight_Disk
{
    [Fact]
    public void Irradiance_below_a_disk_light_matches_the_closed_form()
    {
        // A Lambertian disk of radiance Le and radius R at height h gives, on its axis, E = π Le R² / (h² + R²);
        // a Lambertian receiver then reflects L = kd/π · E.
        const double le = 3.0, radius = 1.0, height = 2.0, kd = 0.9;
        var world = TestScenes.OrthographicWorld(1, 0.001, w => new AreaLightingIntegrator(w), samples: 1024);
        var camera = new OrthographicCamera { Eye = new Point3D(0, 0, 1), LookAt = Point3D.Origin };
        camera.ComputeUVW();
        world.Camera = camera;
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 0, 1)) { Material = new Matte(0, kd, RGBColor.White) });
        var emitter = new Emissive(le);
        var disk = new Disk(new Point3D(0, 0, height), new Normal3D(0, 0, -1), radius) { Material = emitter, CastsShadows = false };
        world.Add(disk);
        world.Add(new AreaLight(disk, emitter));

        var pixel = new Renderer(new RenderOptions { Seed = 11 }).Render(world)[0, 0];
        var expected = kd / Math.PI * Math.PI * le * radius * radius / (height * height + radius * radius);
        Assert.InRange(pixel.r, expected * 0.97, expected * 1.03);
    }

    [Theory]
    [InlineData("path")]
    [InlineData("global")]
    public void Path_and_global_tracers_agree_with_the_closed_form(string kind)
    {
        // Same disk light found by cosine-sampled bounces (path) or by explicit light sampling at the first
        // hit with emitter hits after one bounce discarded (global): both must give kd · Le · R² / (h² + R²).
        const double le = 3.0, radius = 1.0, height = 2.0, kd = 0.9;
        var world = TestScenes.OrthographicWorld(1, 0.001, w => kind == "path" ? new PathIntegrator(w) : new GlobalIntegrator(w), samples: 16384);
        var camera = new OrthographicCamera { Eye = new Point3D(0, 0, 1), LookAt = Point3D.Origin };
        camera.ComputeUVW();
        world.Camera = camera;
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 0, 1)) { Material = new Matte(0, kd, RGBColor.White) });
        var emitter = new Emissive(le);
        var disk = new Disk(new Point3D(0, 0, height), new Normal3D(0, 0, -1), radius) { Material = emitter, CastsShadows = false };
        world.Add(disk);
        world.Add(new AreaLight(disk, emitter));

        var pixel = new Renderer(new RenderOptions { Seed = 12 }).Render(world)[0, 0];
        var expected = kd * le * radius * radius / (height * height + radius * radius);
        Assert.InRange(pixel.r, expected * 0.95, expected * 1.05);
    }

    [Fact]
    public void The_back_of_an_emitter_is_dark()
    {
        var world = TestScenes.OrthographicWorld(1, 0.001, w => new AreaLightingIntegrator(w), samples: 16);
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 0, 1)) { Material = new Matte(0, 1, RGBColor.White) });
        var emitter = new Emissive(3.0);
        var disk = new Disk(new Point3D(0, 0, 2), new Normal3D(0, 0, 1), 1) { Material = emitter, CastsShadows = false };
        world.Add(new AreaLight(disk, emitter));
        var camera = new OrthographicCamera { Eye = new Point3D(0, 0, 1), LookAt = Point3D.Origin };
        camera.ComputeUVW();
        world.Camera = camera;
        Assert.Equal(RGBColor.Black, new Renderer().Render(world)[0, 0]);
    }
}
