using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Showcase;

/// <summary>The default scene: plastic, mirror and glass spheres on a checkered floor under a point light and the sun.</summary>
public class ShowcaseScene : SceneDescription
{
    public override string Name => "spheres";
    public override string Description => "Default: matte, plastic, mirror and glass spheres on a checker floor (Whitted).";

    /// <summary>Objects and lights without camera or tracer, shared by the camera scenes.</summary>
    protected static void AddContent(World world)
    {
        world.BackgroundColor = new RGBColor(0.55, 0.7, 0.9);
        world.AmbientLight = new AmbientLight(0.6, new RGBColor(0.9, 0.95, 1.0));
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 1, 0))
        {
            Material = MaterialFactory.Matte(TextureFactory.PlaneChecker(1.0, new RGBColor(0.9, 0.9, 0.85), new RGBColor(0.25, 0.3, 0.35)), 0.3, 0.7),
        });
        world.Add(new Sphere(new Point3D(-2.3, 1, 0), 1) { Material = MaterialFactory.Plastic(new RGBColor(0.85, 0.2, 0.15)) });
        world.Add(new Sphere(new Point3D(0, 1, -0.8), 1) { Material = MaterialFactory.Mirror(new RGBColor(0.95, 0.95, 0.95)) });
        world.Add(new Sphere(new Point3D(2.3, 1, 0), 1) { Material = MaterialFactory.Glass(new RGBColor(0.75, 0.95, 0.8)) });
        world.Add(new Sphere(new Point3D(0.9, 0.45, 1.6), 0.45) { Material = MaterialFactory.Matte(new RGBColor(0.2, 0.5, 0.9)) });
        world.Add(LightFactory.Point(new Point3D(-4, 8, 6), 1.6));
        world.Add(LightFactory.Directional(new Vector3D(3, 5, 2), 0.9, new RGBColor(1, 0.95, 0.85)));
    }

    protected static readonly Point3D ViewEye = new(0, 3.2, 9);
    protected static readonly Point3D ViewTarget = new(0, 0.9, 0);

    protected override void Populate(World world)
    {
        AddContent(world);
        world.Camera = CameraFactory.Pinhole(ViewEye, ViewTarget, 55, world.ViewPlane);
        world.Integrator = new WhittedIntegrator(world);
    }
}
