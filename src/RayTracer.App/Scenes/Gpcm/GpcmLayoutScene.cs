using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry.Compound;
using RayTracer.Geometry.Parametric;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tracing;
using RayTracer.Viewing;

namespace RayTracer.Scenes.Gpcm;

/// <summary>
/// The "(a) layout and orientation" panels of thesis Figures 6-16, 6-17, 6-19, 6-21 and 6-23: the
/// gallery seen from outside, with a catalogue camera standing at the gallery's eye. Its projection
/// surface, placed where the camera stands, is drawn as a cage of constant-u and constant-v wires
/// (the rows and columns of the image), the eye as a dark ball and the look direction as a rod.
/// </summary>
public sealed class GpcmLayoutScene(string cameraName, double degrees, int figure, int imageWidth, int imageHeight) : GpcmGallery
{
    /// <summary>Across the drawn surface, in scene units: large enough to see, small enough to fit inside the ring.</summary>
    private const double LensSize = 1.5;

    private const int Wires = 9;

    public override string Name => $"gpcm-{cameraName}-layout";

    public override string Description =>
        $"Layout of the {cameraName} GPCM ({degrees:0} degrees) in its gallery, seen from outside (thesis Figure 6-{figure}a).";

    public override int DefaultWidth => 480;
    public override int DefaultHeight => 360;
    protected override string CameraName => cameraName;
    protected override double Degrees => degrees;

    protected override void Populate(World world)
    {
        AddContent(world);
        if (!CameraCatalog.TryFind(cameraName, out var choice))
            throw new InvalidOperationException($"No camera '{cameraName}' in the catalogue.");
        // The drawn camera is built for the image it would take, not for this outside view.
        var plane = new ViewPlane { HorizontalResolution = imageWidth, VerticalResolution = imageHeight };
        var gpcm = (RayTracer.Viewing.Gpcm)choice.Create(degrees, plane, Eye, Target, UpDirection);
        gpcm.SurfaceScale = LensSize / RestSize(gpcm);
        var surface = gpcm.PlacedSurface();

        var cage = new CompoundObject();
        var wire = new TwoSided(MaterialFactory.Plastic(new RGBColor(0.95, 0.75, 0.1), 30));
        for (var k = 0; k < Wires; k++)
        {
            var t = k / (Wires - 1.0);
            cage.Add(new CurveTube(IsoParameterCurve.AtV(surface, t), 0.018, 0.004) { Material = wire });
            cage.Add(new CurveTube(IsoParameterCurve.AtU(surface, t), 0.018, 0.004) { Material = wire });
        }
        world.Add(cage);
        world.Add(new Sphere(Eye, 0.09) { Material = MaterialFactory.Plastic(new RGBColor(0.08, 0.08, 0.1)) });
        var look = (Target - Eye).Normalized();
        world.Add(new Cylinder(Eye, 1.2 * LensSize * look, 0.025, capped: true) { Material = MaterialFactory.Plastic(new RGBColor(0.8, 0.1, 0.1)) });

        world.Camera = Outside(world.ViewPlane);
        world.Integrator = new WhittedIntegrator(world);
    }

    /// <summary>The size of the rest-frame surface: its largest distance from the eye over a grid of (u, v).</summary>
    private static double RestSize(RayTracer.Viewing.Gpcm camera)
    {
        var most = 0.0;
        for (var i = 0; i <= 8; i++)
        for (var j = 0; j <= 8; j++)
        {
            var p = camera.Surface.PointAt(i / 8.0, j / 8.0);
            most = Math.Max(most, Math.Sqrt(p.x * p.x + p.y * p.y + p.z * p.z));
        }
        return most;
    }

    /// <summary>A pinhole above and behind the eye, to its right, looking down at it.</summary>
    private static PinholeCamera Outside(ViewPlane vp)
    {
        var camera = new PinholeCamera
        {
            Eye = Eye + new Vector3D(3.4, 2.6, 4.2),
            LookAt = Eye + new Vector3D(0, -0.5, -0.6),
            Up = UpDirection,
        };
        camera.SetHorizontalFieldOfView(62, vp);
        camera.ComputeUVW();
        return camera;
    }
}
