using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tests.Tracing;
using RayTracer.Tracing;
using RayTracer.Viewing;

namespace RayTracer.Tests.Lights;

public class AreaLight_Shapes
{
    private const double Kd = 0.8, Le = 2.0;

    private static double RenderFloorUnder(Action<RayTracer.Scenes.World> addLight)
    {
        var world = TestScenes.OrthographicWorld(1, 0.0001, w => new AreaLightingIntegrator(w), samples: 4096);
        var camera = new OrthographicCamera { Eye = new Point3D(0, 0, 0.1), LookAt = Point3D.Origin };
        camera.ComputeUVW();
        world.Camera = camera;
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 0, 1)) { Material = new Matte(0, Kd, RGBColor.White) });
        addLight(world);
        return new Renderer(new RenderOptions { Seed = 21 }).Render(world)[0, 0].r;
    }

    /// <summary>Configuration factor from a point to a parallel rectangle a×b at height c above one of its corners.</summary>
    private static double CornerFactor(double a, double b, double c)
    {
        double x = a / c, y = b / c;
        return (x / Math.Sqrt(1 + x * x) * Math.Atan(y / Math.Sqrt(1 + x * x))
              + y / Math.Sqrt(1 + y * y) * Math.Atan(x / Math.Sqrt(1 + y * y))) / (2 * Math.PI);
    }

    [Fact]
    public void Rectangle_light_matches_the_configuration_factor()
    {
        // Centred 2×1 panel at height 1 = four corner rectangles of 1×0.5; E = π Le F, L = kd/π E.
        var value = RenderFloorUnder(world =>
            LightFactory.AddRectangleLight(world, new Point3D(-1, -0.5, 1), new Vector3D(0, 1, 0), new Vector3D(2, 0, 0), Le));
        var expected = Kd * Le * 4 * CornerFactor(1, 0.5, 1);
        Assert.InRange(value, expected * 0.99, expected * 1.01);
    }

    [Fact]
    public void Sphere_light_matches_the_inverse_square_of_its_distance()
    {
        // A uniform spherical emitter of radius R at distance d on the normal gives E = π Le R² / d².
        const double radius = 0.5, distance = 2.0;
        var value = RenderFloorUnder(world => LightFactory.AddSphereLight(world, new Point3D(0, 0, distance), radius, Le));
        var expected = Kd * Le * radius * radius / (distance * distance);
        Assert.InRange(value, expected * 0.99, expected * 1.01);
    }

    [Fact]
    public void Two_triangle_lights_covering_a_rectangle_match_its_configuration_factor()
    {
        // The same 2×1 panel as above, split along a diagonal into two triangle lights facing down.
        var corner = new Point3D(-1, -0.5, 1);
        var a = new Vector3D(0, 1, 0);
        var b = new Vector3D(2, 0, 0);
        var value = RenderFloorUnder(world =>
        {
            LightFactory.AddAreaLight(world, new Triangle(corner, corner + a, corner + b), Le);
            LightFactory.AddAreaLight(world, new Triangle(corner + a + b, corner + b, corner + a), Le);
        });
        var expected = Kd * Le * 4 * CornerFactor(1, 0.5, 1);
        Assert.InRange(value, expected * 0.99, expected * 1.01);
    }
}
