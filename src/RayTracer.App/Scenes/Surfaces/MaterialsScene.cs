using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Surfaces;

/// <summary>
/// A row of five spheres on a checker floor in front of a striped wall, each with a material chosen by the
/// derived scene, lit by a rectangle light; the same stage for every material kind.
/// </summary>
public abstract class MaterialsScene : SceneDescription
{
    public override int DefaultSamples => 25;
    public override int DefaultMaxDepth => 6;

    protected abstract Material MaterialFor(int index);

    protected override void Populate(World world)
    {
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
        for (var i = 0; i < 5; i++)
            world.Add(new Sphere(new Point3D(-4 + 2 * i, 0.85, 0), 0.85) { Material = MaterialFor(i) });
        LightFactory.AddRectangleLight(world, new Point3D(-3, 5, -0.5), new Vector3D(6, 0, 0), new Vector3D(0, 0, 2.5), 3.0);
        world.Add(LightFactory.Point(new Point3D(5, 6, 8), 0.6));
        world.Camera = CameraFactory.Pinhole(new Point3D(0, 2.4, 9), new Point3D(0, 0.9, 0), 58, world.ViewPlane);
        world.Integrator = new AreaLightingIntegrator(world);
    }
}
