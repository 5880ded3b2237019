using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry;
using RayTracer.Geometry.Generic;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Primitives;

/// <summary>Generic (origin-centred) objects placed by instancing: torus, cone, cylinders, part objects, annulus, sphere (as an ellipsoid), disk, rectangle and plane.</summary>
public sealed class GenericPrimitivesScene : SceneDescription
{
    public override string Name => "primitives-generic";
    public override string Description => "Generic torus, cone, cylinders, part objects, annulus, ellipsoid, disk, rectangle and plane, placed by instances.";

    private static void Place(World world, GeometricObject obj, RGBColor color, double x, double z, double tilt = 0)
    {
        var instance = new Instance(obj).RotateX(tilt).Translate(x, 0, z);
        instance.Material = MaterialFactory.Plastic(color);
        world.Add(instance);
    }

    protected override void Populate(World world)
    {
        world.BackgroundColor = new RGBColor(0.08, 0.08, 0.1);
        world.AmbientLight = new AmbientLight(0.45);
        world.Add(WithMaterial(new Instance(new GenericPlane()).Translate(0, -1, 0), MaterialFactory.Matte(new RGBColor(0.75, 0.75, 0.7))));
        Place(world, new Torus(0.8, 0.3), new RGBColor(0.9, 0.5, 0.1), -3, 0, 0.6);
        Place(world, new Instance(new Cone(1.8, 0.8)).Translate(0, -1, 0), new RGBColor(0.2, 0.7, 0.3), -1, 0);
        Place(world, new OpenCylinder(-1, 0.6, 0.6), new RGBColor(0.3, 0.5, 0.95), 1, 0);
        Place(world, new PartSphere(0.9, 0, 1.5 * Math.PI, 0, 0.75 * Math.PI), new RGBColor(0.9, 0.2, 0.3), 3, 0);
        Place(world, new PartTorus(0.7, 0.25, 0, 1.5 * Math.PI), new RGBColor(0.8, 0.8, 0.2), -2, -2.5, 0.9);
        Place(world, new PartCylinder(-1, 0.8, 0.7, 0, Math.PI), new RGBColor(0.6, 0.3, 0.8), 0.2, -2.5);
        Place(world, new Instance(new Annulus(0.4, 0.9)).RotateX(1.2), new RGBColor(0.2, 0.8, 0.8), 2.4, -2.5);
        // Scaling a generic sphere gives an ellipsoid; generic disk and rectangle stand up by rotation.
        world.Add(WithMaterial(new Instance(new GenericSphere()).Scale(0.5, 1.0, 0.5).Translate(4.4, 0, -2.5), MaterialFactory.Plastic(new RGBColor(0.95, 0.6, 0.7))));
        world.Add(WithMaterial(new Instance(new GenericDisk(0.8)).RotateX(1.3).Translate(-4.3, 0, -2.6), MaterialFactory.Matte(new RGBColor(0.5, 0.9, 0.4))));
        world.Add(WithMaterial(new Instance(new GenericRectangle(2.5, 0.9)).RotateX(Math.PI / 2).Translate(0, 0.2, -4.5), MaterialFactory.Matte(new RGBColor(0.55, 0.6, 0.8))));
        world.Add(LightFactory.Point(new Point3D(3, 7, 8), 1.5));
        world.Add(LightFactory.Directional(new Vector3D(-3, 5, 2), 0.4));
        world.Camera = CameraFactory.Pinhole(new Point3D(0, 2.8, 8), new Point3D(0, -0.2, -1), 60, world.ViewPlane);
        world.Integrator = new RayCastIntegrator(world);
    }
}
