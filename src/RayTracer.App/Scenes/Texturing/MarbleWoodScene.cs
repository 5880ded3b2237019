using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry;
using RayTracer.Geometry.Compound;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Texturing;

/// <summary>Marble (ramp indexed by noise-bent bands) and wood (noise-perturbed rings) solid textures.</summary>
public sealed class MarbleWoodScene : SceneDescription
{
    public override string Name => "texture-marble-wood";
    public override string Description => "Marble ramp and wood solid textures on spheres, a box and a cylinder.";

    protected override void Populate(World world)
    {
        world.BackgroundColor = new RGBColor(0.12, 0.12, 0.14);
        world.AmbientLight = new AmbientLight(0.45);
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 1, 0)) { Material = MaterialFactory.Matte(TextureFactory.Wood(7), 0.3, 0.7) });
        world.Add(new Sphere(new Point3D(-2.2, 1.1, 0), 1.1) { Material = MaterialFactory.Plastic(TextureFactory.Marble(), 80) });
        world.Add(new Box(new Point3D(-0.6, 0, -0.9), new Point3D(0.9, 1.5, 0.6)) { Material = MaterialFactory.Plastic(TextureFactory.Marble(99), 80) });
        world.Add(WithMaterial(new Instance(new SolidCylinder(0, 2, 0.8)).Translate(2.4, 0, 0), MaterialFactory.Plastic(TextureFactory.Wood(), 30)));
        world.Add(LightFactory.Point(new Point3D(-3, 7, 7), 1.2));
        world.Add(LightFactory.Directional(new Vector3D(3, 4, 3), 0.4));
        world.Camera = CameraFactory.Pinhole(new Point3D(0, 3, 8), new Point3D(0, 0.9, 0), 55, world.ViewPlane);
        world.Integrator = new RayCastIntegrator(world);
    }
}
