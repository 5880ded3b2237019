using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Gpcm;

/// <summary>
/// A ring of objects all round a generalized pinhole camera (thesis §6.5.4, Figures 6-16 to 6-24): the
/// eye stands in the middle of a checkered floor, so panoramas show something in every direction. Each
/// subclass picks a camera of <see cref="CameraCatalog"/>; any other can be put in its place with
/// <c>render --camera</c>.
/// </summary>
public abstract class GpcmGallery : SceneDescription
{
    public static readonly Point3D Eye = new(0, 1.6, 0);
    public static readonly Point3D Target = new(0, 1.2, -6);
    public static readonly Vector3D UpDirection = new(0, 1, 0);

    private static readonly RGBColor[] Palette =
    [
        new(0.85, 0.2, 0.15), new(0.95, 0.6, 0.1), new(0.9, 0.85, 0.2), new(0.3, 0.75, 0.25),
        new(0.15, 0.6, 0.75), new(0.2, 0.35, 0.9), new(0.55, 0.25, 0.8), new(0.85, 0.3, 0.6),
    ];

    /// <summary>The camera's catalogue name and its field of view in degrees.</summary>
    protected abstract string CameraName { get; }
    protected abstract double Degrees { get; }

    public override int DefaultSamples => 4;

    protected override void Populate(World world)
    {
        AddContent(world);
        if (!CameraCatalog.TryFind(CameraName, out var choice))
            throw new InvalidOperationException($"No camera '{CameraName}' in the catalogue.");
        world.Camera = choice.Create(Degrees, world.ViewPlane, Eye, Target, UpDirection);
        world.Integrator = new WhittedIntegrator(world);
    }

    /// <summary>
    /// Eight objects on a circle of radius 6 about the eye, one every 45°, alternating spheres and capped
    /// cylinders in the palette's colours; a mirror sphere and a glass sphere nearer in; and four tall
    /// columns further out, between the ring's objects. The red sphere is straight ahead (−z).
    /// </summary>
    protected static void AddContent(World world)
    {
        world.BackgroundColor = new RGBColor(0.55, 0.7, 0.9);
        world.AmbientLight = new AmbientLight(0.55, new RGBColor(0.9, 0.95, 1.0));
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 1, 0))
        {
            Material = MaterialFactory.Matte(TextureFactory.PlaneChecker(1.0, new RGBColor(0.9, 0.9, 0.85), new RGBColor(0.3, 0.32, 0.38)), 0.3, 0.7),
        });
        for (var k = 0; k < 8; k++)
        {
            var angle = k * Math.PI / 4;
            var centre = new Point3D(6 * Math.Sin(angle), 0, -6 * Math.Cos(angle));
            var material = MaterialFactory.Plastic(Palette[k]);
            if (k % 2 == 0)
                world.Add(new Sphere(centre + new Vector3D(0, 1.1, 0), 1.1) { Material = material });
            else
                world.Add(new Cylinder(centre, new Vector3D(0, 2.4, 0), 0.8, capped: true) { Material = material });
        }
        for (var k = 0; k < 4; k++)
        {
            var angle = Math.PI / 8 + k * Math.PI / 2;
            var foot = new Point3D(10 * Math.Sin(angle), 0, -10 * Math.Cos(angle));
            world.Add(new Cylinder(foot, new Vector3D(0, 7, 0), 0.45, capped: true) { Material = MaterialFactory.Matte(new RGBColor(0.92, 0.9, 0.86)) });
        }
        world.Add(new Sphere(new Point3D(-2.2, 0.8, -3.2), 0.8) { Material = MaterialFactory.Mirror(new RGBColor(0.95, 0.95, 0.95)) });
        world.Add(new Sphere(new Point3D(2.4, 0.7, 2.6), 0.7) { Material = MaterialFactory.Glass(new RGBColor(0.75, 0.95, 0.8)) });
        world.Add(LightFactory.Point(new Point3D(-3, 9, 4), 1.4));
        world.Add(LightFactory.Directional(new Vector3D(3, 5, 2), 0.9, new RGBColor(1, 0.95, 0.85)));
    }
}
