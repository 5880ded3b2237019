using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Scenes;
using RayTracer.Tracing;

namespace RayTracer.Tests.Tracing;

/// <summary>
/// Glass, diamond, simple-glass and mirror spheres on a checker floor under point and ambient light, traced
/// Whitted style: deterministic (no sampled lights), so two renders differ only where the tracer does.
/// </summary>
internal static class GlassScene
{
    public static World Build(int maxDepth, double minimumThroughput, int width = 40, int height = 30)
    {
        var world = new World();
        world.ViewPlane = new() { HorizontalResolution = width, VerticalResolution = height, MaxDepth = maxDepth, Gamma = 2.2 };
        world.ViewPlane.MinimumThroughput = minimumThroughput;
        world.BackgroundColor = new RGBColor(0.15, 0.17, 0.2);
        world.AmbientLight = new AmbientLight(0.35);
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 1, 0))
        {
            Material = MaterialFactory.Matte(TextureFactory.PlaneChecker(0.8, new RGBColor(0.85, 0.85, 0.8), new RGBColor(0.3, 0.3, 0.35))),
        });
        world.Add(new Plane(new Point3D(0, 0, -3), new Normal3D(0, 0, 1))
        {
            Material = MaterialFactory.Matte(TextureFactory.Checker3D(1.0, new RGBColor(0.7, 0.3, 0.25), new RGBColor(0.9, 0.8, 0.5))),
        });
        Material[] materials =
        [
            new Dielectric(1.5, 1.0),
            new Dielectric(2.4, 1.0, new RGBColor(0.9, 0.9, 1.0)),
            new Dielectric(1.33, 1.0, new RGBColor(0.8, 0.95, 1.0)),
            new Transparent(ior: 1.5),
            MaterialFactory.Mirror(new RGBColor(0.9, 0.95, 1.0)),
        ];
        for (var i = 0; i < materials.Length; i++)
            world.Add(new Sphere(new Point3D(-4 + 2 * i, 0.85, 0), 0.85) { Material = materials[i] });
        world.Add(new PointLight(new Point3D(5, 6, 8), 1.2));
        world.Add(new PointLight(new Point3D(-4, 7, 3), 0.8));
        world.Camera = CameraFactory.Pinhole(new Point3D(0, 2.4, 9), new Point3D(0, 0.9, 0), 58, world.ViewPlane);
        world.Integrator = new WhittedIntegrator(world);
        return world;
    }
}
