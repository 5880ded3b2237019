using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Primitives;

/// <summary>Each universal primitive once: sphere, box, oriented box, capped cylinder, disk, rectangle, triangle on a plane.</summary>
public sealed class UniversalPrimitivesScene : SceneDescription
{
    public override string Name => "primitives-universal";
    public override string Description => "Sphere, axis-aligned and oriented boxes, cylinder, disk, rectangle and triangle in general position.";

    protected override void Populate(World world)
    {
        world.BackgroundColor = new RGBColor(0.1, 0.12, 0.15);
        world.AmbientLight = new AmbientLight(0.4);
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 1, 0)) { Material = MaterialFactory.Matte(new RGBColor(0.7, 0.7, 0.7)) });
        world.Add(new Sphere(new Point3D(-3, 1, 0), 1) { Material = MaterialFactory.Plastic(new RGBColor(0.9, 0.3, 0.2)) });
        world.Add(new Box(new Point3D(-1.5, 0, -0.7), new Point3D(-0.1, 1.4, 0.7)) { Material = MaterialFactory.Plastic(new RGBColor(0.3, 0.8, 0.3)) });
        world.Add(new Cylinder(new Point3D(1, 0, 0), new Vector3D(0.3, 1.8, -0.2), 0.6, capped: true) { Material = MaterialFactory.Plastic(new RGBColor(0.3, 0.4, 0.9)) });
        world.Add(new Disk(new Point3D(3, 1.2, -0.5), new Normal3D(-0.4, 0.3, 1).Normalized(), 0.9) { Material = MaterialFactory.Matte(new RGBColor(0.9, 0.8, 0.2)) });
        world.Add(new Rectangle(new Point3D(-2.5, 2.6, -2), new Vector3D(2.2, 0, 0), new Vector3D(0, 1.2, 0.4)) { Material = MaterialFactory.Matte(new RGBColor(0.8, 0.4, 0.8)) });
        world.Add(new Triangle(new Point3D(0.5, 2.4, -2), new Point3D(3, 2.6, -2.5), new Point3D(1.6, 4, -2.2)) { Material = MaterialFactory.Matte(new RGBColor(0.3, 0.9, 0.9)) });
        world.Add(new OrientedBox(new Point3D(-2.4, 0.7, 3.0), new Vector3D(1, 0.5, 0.3), new Vector3D(-0.2, 1, 0.4), new Vector3D(0.6, 0.5, 0.4))
        {
            Material = MaterialFactory.Plastic(new RGBColor(0.95, 0.6, 0.3)),
        });
        world.Add(LightFactory.Point(new Point3D(4, 8, 7), 1.4));
        world.Add(LightFactory.Directional(new Vector3D(-2, 4, 3), 0.5));
        world.Camera = CameraFactory.Pinhole(new Point3D(0, 3, 9), new Point3D(0, 1.3, 0), 60, world.ViewPlane);
        world.Integrator = new RayCastIntegrator(world);
    }
}
