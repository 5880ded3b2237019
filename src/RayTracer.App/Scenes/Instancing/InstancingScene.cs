using RayTracer.Acceleration;
using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Instancing;

/// <summary>
/// A scene of thesis Figure 7-3: tubes (<see cref="Cylinders"/>) built by one <see cref="CylinderMethod"/>
/// and held in one hierarchy, on a stage that every method shares, so that only the tubes differ
/// between the five renders. One sample per pixel, as the timing compares the tests, not the image.
/// </summary>
public abstract class InstancingScene : SceneDescription
{
    public CylinderMethod Method { get; init; } = CylinderMethod.GauCyl;

    /// <summary>Wraps each tube as it is built (the experiment counts tests through it); none by default.</summary>
    public Func<GeometricObject, GeometricObject>? Wrap { get; init; }

    public override int DefaultWidth => 640;
    public override int DefaultHeight => 480;
    public override int DefaultSamples => 1;

    /// <summary>The scene's tubes, the same for every method.</summary>
    public abstract IReadOnlyList<CylinderSpec> Cylinders();

    protected override void Populate(World world)
    {
        var specs = Cylinders();
        var tubes = new List<GeometricObject>();
        foreach (var spec in specs)
        {
            var tube = spec.Create(Method);
            tubes.Add(Wrap is null ? tube : Wrap(tube));
        }

        // Round joints between the tubes of a curve, the same for every method and not counted.
        if (Joints)
        {
            foreach (var spec in specs)
                tubes.Add(new Sphere(spec.Base + spec.Axis, spec.Radius) { Material = spec.Material });
        }

        world.Add(new Bvh(tubes));
        Stage(world);
    }

    /// <summary>Whether a sphere of the tube's radius closes each joint (curves drawn as tubes).</summary>
    protected virtual bool Joints => true;

    /// <summary>Floor, other objects, lights, camera and tracer.</summary>
    protected abstract void Stage(World world);

    protected static readonly RGBColor Background = new(0.12, 0.13, 0.16);

    protected static void AddFloor(World world, double y, RGBColor colour)
    {
        world.BackgroundColor = Background;
        world.AmbientLight = new AmbientLight(0.4);
        world.Add(new Plane(new Point3D(0, y, 0), new Normal3D(0, 1, 0)) { Material = MaterialFactory.Matte(colour, 0.3, 0.7) });
    }

    protected static void AddLights(World world, Point3D key)
    {
        world.Add(LightFactory.Point(key, 1.0));
        world.Add(new DirectionalLight(new Vector3D(1, 0.6, 0.8), 0.3) { CastsShadows = false });
    }

    protected static void SetCamera(World world, Point3D eye, Point3D lookAt, double horizontalFovDegrees, bool reflections)
    {
        world.Camera = CameraFactory.Pinhole(eye, lookAt, horizontalFovDegrees, world.ViewPlane);
        world.Integrator = reflections ? new WhittedIntegrator(world) : new RayCastIntegrator(world);
    }

    /// <summary>Plastic; tubes turn their normal towards the ray, so the inner wall shades too.</summary>
    protected static Material TubeMaterial(RGBColor colour) => MaterialFactory.Plastic(colour, 40);

    /// <summary>A Twister point with z up as a ray tracer point with y up, scaled and moved.</summary>
    protected static Point3D Upright(global::Twister.TwistablePoint p, double scale, Vector3D offset) =>
        new Point3D(p.x * scale, p.z * scale, -p.y * scale) + offset;

    /// <summary>Consecutive samples of a curve (Twister's z up turned to y up) joined by tubes.</summary>
    protected static List<CylinderSpec> Polyline(IReadOnlyList<Point3D> points, double radius, Material material)
    {
        var specs = new List<CylinderSpec>();
        for (var i = 1; i < points.Count; i++)
        {
            var axis = points[i] - points[i - 1];
            if (axis.LengthSquared > 0)
                specs.Add(new CylinderSpec(points[i - 1], axis, radius, material));
        }

        return specs;
    }
}
