using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry;
using RayTracer.Geometry.Generic;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Lighting;

/// <summary>
/// A floor, a back wall and a few objects; each lighting scene derives from it and only adds its lights, so
/// the light kinds can be compared on the same content.
/// </summary>
public abstract class RoomScene : SceneDescription
{
    public override int DefaultSamples => 25;

    protected override void Populate(World world)
    {
        world.BackgroundColor = RGBColor.Black;
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 1, 0)) { Material = MaterialFactory.Matte(new RGBColor(0.75, 0.75, 0.72), 0.25, 0.75) });
        world.Add(new Plane(new Point3D(0, 0, -3), new Normal3D(0, 0, 1)) { Material = MaterialFactory.Matte(new RGBColor(0.6, 0.65, 0.75), 0.25, 0.75) });
        world.Add(new Sphere(new Point3D(-1.6, 1, 0), 1) { Material = MaterialFactory.Matte(new RGBColor(0.85, 0.3, 0.2)) });
        world.Add(new Box(new Point3D(0.2, 0, -1.2), new Point3D(1.4, 1.8, 0)) { Material = MaterialFactory.Matte(new RGBColor(0.3, 0.7, 0.35)) });
        world.Add(WithMaterial(new Instance(new Torus(0.6, 0.22)).RotateX(1.1).Translate(2.4, 0.75, 0.8), MaterialFactory.Plastic(new RGBColor(0.25, 0.4, 0.9))));
        AddLights(world);
        world.Camera = CameraFactory.Pinhole(new Point3D(0, 2.6, 8), new Point3D(0, 1, 0), 55, world.ViewPlane);
        world.Integrator ??= new AreaLightingIntegrator(world);
    }

    protected abstract void AddLights(World world);
}
