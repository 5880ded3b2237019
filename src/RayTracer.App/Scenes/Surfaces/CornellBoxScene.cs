using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Surfaces;

/// <summary>
/// A Cornell-style box (red and green side walls, ceiling light, two blocks) rendered by path tracing: colour
/// bleeding and soft indirect light come from the sampled bounces.
/// </summary>
public class CornellBoxScene : SceneDescription
{
    public override string Name => "path-tracing";
    public override string Description => "Cornell box with an emissive ceiling panel, path traced (indirect light, colour bleeding).";
    public override int DefaultWidth => 300;
    public override int DefaultHeight => 300;
    public override int DefaultSamples => 100;
    public override int DefaultMaxDepth => 6;

    protected virtual Integrator CreateIntegrator(World world) => new PathIntegrator(world);

    protected override void Populate(World world)
    {
        var white = new Matte(0, 0.75, new RGBColor(0.9, 0.9, 0.9));
        var red = new Matte(0, 0.75, new RGBColor(0.85, 0.15, 0.1));
        var green = new Matte(0, 0.75, new RGBColor(0.15, 0.75, 0.2));
        const double s = 5.0;
        // Walls as rectangles with normals facing into the box.
        world.Add(new Rectangle(new Point3D(0, 0, 0), new Vector3D(0, 0, s), new Vector3D(s, 0, 0), new Normal3D(0, 1, 0)) { Material = white });
        world.Add(new Rectangle(new Point3D(0, s, 0), new Vector3D(s, 0, 0), new Vector3D(0, 0, s), new Normal3D(0, -1, 0)) { Material = white });
        world.Add(new Rectangle(new Point3D(0, 0, 0), new Vector3D(s, 0, 0), new Vector3D(0, s, 0), new Normal3D(0, 0, 1)) { Material = white });
        world.Add(new Rectangle(new Point3D(0, 0, 0), new Vector3D(0, s, 0), new Vector3D(0, 0, s), new Normal3D(1, 0, 0)) { Material = red });
        world.Add(new Rectangle(new Point3D(s, 0, 0), new Vector3D(0, 0, s), new Vector3D(0, s, 0), new Normal3D(-1, 0, 0)) { Material = green });
        world.Add(WithMaterial(new Instance(new Box(new Point3D(-0.8, 0, -0.8), new Point3D(0.8, 3, 0.8))).RotateY(0.35).Translate(1.7, 0, 1.8), white));
        world.Add(WithMaterial(new Instance(new Box(new Point3D(-0.75, 0, -0.75), new Point3D(0.75, 1.5, 0.75))).RotateY(-0.3).Translate(3.4, 0, 3.2), white));
        // A fairly large panel: pure path tracing only finds light when a bounce happens to hit it.
        var panel = new Rectangle(new Point3D(1.0, s - 1e-3, 1.0), new Vector3D(3, 0, 0), new Vector3D(0, 0, 3), new Normal3D(0, -1, 0));
        LightFactory.AddAreaLight(world, panel, 4.5, new RGBColor(1, 0.9, 0.75));
        // From 10 units in front of the opening a 28° view just fits the box's front edges.
        world.Camera = CameraFactory.Pinhole(new Point3D(s / 2, s / 2, s + 10), new Point3D(s / 2, s / 2, 0), 28, world.ViewPlane);
        world.Integrator = CreateIntegrator(world);
    }
}
