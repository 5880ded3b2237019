using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Maths;
using RayTracer.Textures.Patterns;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Primitives;

/// <summary>Binary objects: a sphere and a rectangle cut by binary textures, showing the inside through the holes.</summary>
public sealed class BinaryObjectScene : SceneDescription
{
    public override string Name => "primitives-binary";
    public override string Description => "Sphere and rectangle kept only where a binary checker texture is true.";

    protected override void Populate(World world)
    {
        world.BackgroundColor = new RGBColor(0.2, 0.25, 0.3);
        world.AmbientLight = new AmbientLight(0.5);
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 1, 0)) { Material = MaterialFactory.Matte(new RGBColor(0.8, 0.8, 0.75)) });
        var checks = new SphereChecker(12, 6) { Center = new Point3D(-1.3, 1.2, 0) };
        world.Add(new BinaryObject(new Sphere(new Point3D(-1.3, 1.2, 0), 1.2), checks.GetValue) { Material = MaterialFactory.Plastic(new RGBColor(0.9, 0.4, 0.1)) });
        var squares = new Checker2D(5, 5);
        world.Add(new BinaryObject(new Rectangle(new Point3D(0.9, 0.1, -1), new Vector3D(2.2, 0, 0.6), new Vector3D(0, 2.4, 0)), squares.GetValue)
        {
            Material = MaterialFactory.Matte(new RGBColor(0.2, 0.6, 0.9)),
        });
        world.Add(LightFactory.Point(new Point3D(2, 7, 6), 1.3));
        world.Camera = CameraFactory.Pinhole(new Point3D(0, 2.5, 7), new Point3D(0, 1.1, 0), 55, world.ViewPlane);
        world.Integrator = new RayCastIntegrator(world);
    }
}
