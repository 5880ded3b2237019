using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Maths;
using RayTracer.Textures.Conversions;
using RayTracer.Textures.Mappings;
using RayTracer.Textures.Patterns;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Texturing;

/// <summary>The four checkers: 2D (on a rectangle's own uv and spherically mapped), 3D solid, sphere and plane checkers.</summary>
public sealed class CheckersScene : SceneDescription
{
    public override string Name => "texture-checkers";
    public override string Description => "2D, 3D, sphere and plane checker textures.";

    protected override void Populate(World world)
    {
        world.BackgroundColor = new RGBColor(0.1, 0.1, 0.12);
        world.AmbientLight = new AmbientLight(0.5);
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 1, 0))
        {
            Material = MaterialFactory.Matte(TextureFactory.PlaneChecker(0.7, new RGBColor(0.9, 0.9, 0.9), new RGBColor(0.2, 0.2, 0.25))),
        });
        world.Add(new Sphere(new Point3D(-3, 1, 0), 1)
        {
            Material = MaterialFactory.Matte(TextureFactory.SphereChecker(16, 8, new RGBColor(0.9, 0.2, 0.2), new RGBColor(0.95, 0.95, 0.9), new Point3D(-3, 1, 0))),
        });
        world.Add(new Sphere(new Point3D(-0.8, 1, 0), 1)
        {
            Material = MaterialFactory.Matte(TextureFactory.Checker3D(0.45, new RGBColor(0.2, 0.6, 0.9), new RGBColor(0.95, 0.9, 0.5))),
        });
        // A 2D checker wrapped on a unit sphere by the spherical mapping; the instance keeps the local hit point on the unit sphere.
        var mapped = new BinaryColorTexture(new Checker2D(12, 6) { Mapping = new SphericalMapping() }, new RGBColor(0.2, 0.8, 0.3), new RGBColor(0.1, 0.1, 0.1));
        world.Add(WithMaterial(new Instance(new Sphere(Point3D.Origin, 1)).Translate(1.4, 1, 0), MaterialFactory.Matte(mapped)));
        world.Add(new Rectangle(new Point3D(2.6, 0.1, -1), new Vector3D(1.4, 0, 0.4), new Vector3D(0, 2.2, 0))
        {
            Material = MaterialFactory.Matte(TextureFactory.Checker2D(4, 6, new RGBColor(0.9, 0.6, 0.1), new RGBColor(0.3, 0.15, 0.05))),
        });
        world.Add(LightFactory.Point(new Point3D(3, 8, 8), 1.2));
        world.Camera = CameraFactory.Pinhole(new Point3D(0, 2.5, 8), new Point3D(0, 1, 0), 62, world.ViewPlane);
        world.Integrator = new RayCastIntegrator(world);
    }
}
