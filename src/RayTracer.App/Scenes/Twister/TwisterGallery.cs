using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry;
using RayTracer.Geometry.Compound;
using RayTracer.Geometry.Parametric;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tracing;
using Twister;

namespace RayTracer.Scenes.Twister;

/// <summary>
/// What the Twister galleries (thesis Figures 6-1, 6-7 to 6-12) share: a studio with a ground and a
/// backdrop, a key light that casts shadows and a soft fill, a palette, and the placing of Twister
/// shapes. Twister draws with z up; the ray tracer has y up, so shapes are turned a quarter turn about x
/// (Twister's z becomes y, its y becomes −z) unless they are plane curves shown face on.
/// </summary>
public abstract class TwisterGallery : SceneDescription
{
    /// <summary>Colours that stay apart next to each other and under the same light.</summary>
    protected static readonly RGBColor[] Palette =
    [
        new(0.80, 0.25, 0.20), // brick red
        new(0.20, 0.45, 0.75), // blue
        new(0.90, 0.65, 0.15), // amber
        new(0.25, 0.60, 0.35), // green
        new(0.55, 0.30, 0.65), // violet
        new(0.15, 0.60, 0.65), // teal
        new(0.85, 0.45, 0.55), // rose
        new(0.45, 0.40, 0.30), // bronze
        new(0.70, 0.70, 0.68), // pale gray
    ];

    protected static readonly RGBColor Background = new(0.14, 0.15, 0.18);
    protected static readonly RGBColor StageColor = new(0.70, 0.68, 0.64);

    /// <summary>Plastic in the palette's <paramref name="index"/>th colour (wrapping), lit alike on both faces.</summary>
    protected static Material PaletteMaterial(int index) =>
        new TwoSided(MaterialFactory.Plastic(Palette[index % Palette.Length], 40));

    /// <summary>A tube of <paramref name="radius"/> around the curve; the axis strays from the curve by at most a fifth of the radius.</summary>
    protected static CurveTube Tube(IParametricCurve curve, double radius) => new(curve, radius, radius / 5);

    /// <summary>
    /// Adds plane curves face on, as tubes in the palette's colours from <paramref name="colour"/>, centred
    /// together in the cell (<paramref name="column"/>, <paramref name="row"/>) of a grid of square cells
    /// of side <paramref name="cell"/> centred on the origin of the plane z = 0; row 0 is the top.
    /// </summary>
    protected static void AddFaceOn(World world, IReadOnlyList<IParametricCurve> curves, double tubeRadius, int colour,
        int column, int row, int columns, int rows, double cell)
    {
        var group = new CompoundObject();
        for (var i = 0; i < curves.Count; i++)
        {
            group.Add(new CurveTube(curves[i], tubeRadius, tubeRadius / 5) { Material = PaletteMaterial(colour + i) });
        }

        var centre = new Point3D((column - (columns - 1) / 2.0) * cell, ((rows - 1) / 2.0 - row) * cell, 0);
        world.Add(CentredAt(group, centre));
    }

    /// <summary>Twister's z axis turned to the ray tracer's y axis.</summary>
    protected static Instance Upright(GeometricObject shape) => new Instance(shape).RotateX(-Math.PI / 2);

    /// <summary>The object moved so the centre of its bounding box is <paramref name="centre"/>.</summary>
    protected static Instance CentredAt(GeometricObject shape, Point3D centre)
    {
        var instance = shape as Instance ?? new Instance(shape);
        var box = instance.GetBoundingBox();
        var middle = Point3D.Lerp(box.Min, box.Max, 0.5);
        return instance.Translate(centre.x - middle.x, centre.y - middle.y, centre.z - middle.z);
    }

    /// <summary>The object moved so its bounding box stands on the plane y = <paramref name="groundY"/>, centred over (x, z).</summary>
    protected static Instance StandingAt(GeometricObject shape, double x, double z, double groundY = 0)
    {
        var instance = shape as Instance ?? new Instance(shape);
        var box = instance.GetBoundingBox();
        var middle = Point3D.Lerp(box.Min, box.Max, 0.5);
        return instance.Translate(x - middle.x, groundY - box.Min.y, z - middle.z);
    }

    /// <summary>A ground at y = <paramref name="groundY"/> and, if <paramref name="backdropZ"/> is given, an upright backdrop facing +z.</summary>
    protected static void AddStage(World world, double groundY, double? backdropZ = null)
    {
        world.BackgroundColor = Background;
        world.AmbientLight = new AmbientLight(0.45);
        world.Add(new Plane(new Point3D(0, groundY, 0), new Normal3D(0, 1, 0)) { Material = MaterialFactory.Matte(StageColor, 0.3, 0.7) });
        if (backdropZ is { } z)
        {
            world.Add(new Plane(new Point3D(0, 0, z), new Normal3D(0, 0, 1)) { Material = MaterialFactory.Matte(StageColor * 0.9, 0.3, 0.7) });
        }
    }

    /// <summary>
    /// The studio for plane curves shown face on at z = 0: a backdrop close behind and a key light near
    /// the camera's line of sight, so each curve throws a small drop shadow that does not tangle with it.
    /// </summary>
    protected static void AddFaceOnStudio(World world, double groundY)
    {
        AddStage(world, groundY, -0.8);
        AddLights(world, new Point3D(-1.2, 2.5, 16));
    }

    /// <summary>A key light above and to the left of the camera (shadows) and a fill from the right (none).</summary>
    protected static void AddLights(World world, Point3D key, double keyRadiance = 1.0)
    {
        world.Add(LightFactory.Point(key, keyRadiance));
        world.Add(new DirectionalLight(new Vector3D(1, 0.5, 0.8), 0.35) { CastsShadows = false });
    }

    protected static void SetCamera(World world, Point3D eye, Point3D lookAt, double horizontalFovDegrees)
    {
        world.Camera = CameraFactory.Pinhole(eye, lookAt, horizontalFovDegrees, world.ViewPlane);
        world.Integrator = new RayCastIntegrator(world);
    }
}
