using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry;
using RayTracer.Geometry.Compound;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Primitives;

/// <summary>Compound objects: beveled box, solid cylinder and beveled cylinder, plus rotated instances of them.</summary>
public sealed class CompoundObjectsScene : SceneDescription
{
    public override string Name => "primitives-compound";
    public override string Description => "Beveled box, solid cylinder and beveled cylinder, some rotated by instances.";

    protected override void Populate(World world)
    {
        world.BackgroundColor = new RGBColor(0.12, 0.1, 0.1);
        world.AmbientLight = new AmbientLight(0.4);
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 1, 0)) { Material = MaterialFactory.Matte(new RGBColor(0.7, 0.72, 0.75)) });
        world.Add(new BeveledBox(new Point3D(-3.2, 0, -0.8), new Point3D(-1.6, 1.6, 0.8), 0.2) { Material = MaterialFactory.Plastic(new RGBColor(0.85, 0.55, 0.2)) });
        world.Add(new Instance(new SolidCylinder(0, 1.8, 0.7)) { Material = MaterialFactory.Plastic(new RGBColor(0.25, 0.55, 0.9)) });
        world.Add(WithMaterial(new Instance(new BeveledCylinder(-0.9, 0.9, 0.7, 0.15)).RotateZ(Math.PI / 2).RotateY(0.5).Translate(2.5, 0.7, 0),
            MaterialFactory.Shiny(new RGBColor(0.8, 0.2, 0.3))));
        world.Add(WithMaterial(new Instance(new BeveledBox(new Point3D(-0.5, -0.5, -0.5), new Point3D(0.5, 0.5, 0.5), 0.12)).RotateY(0.7).RotateX(0.5).Translate(0.2, 0.6, 2.2),
            MaterialFactory.Plastic(new RGBColor(0.4, 0.8, 0.4))));
        world.Add(LightFactory.Point(new Point3D(-3, 8, 7), 1.4));
        world.Add(LightFactory.Directional(new Vector3D(3, 4, 2), 0.5));
        world.Camera = CameraFactory.Pinhole(new Point3D(0, 3.5, 8.5), new Point3D(0, 0.7, 0), 55, world.ViewPlane);
        world.Integrator = new WhittedIntegrator(world);
    }
}
