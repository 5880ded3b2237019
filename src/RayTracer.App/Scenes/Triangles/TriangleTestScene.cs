using RayTracer.Acceleration;
using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry.Meshes;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Scenes.Meshes;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Triangles;

/// <summary>
/// One mesh of the ray–triangle experiment (thesis Figure 7-8) in a BIH, smooth shaded, standing on a
/// checkered floor under a key light that casts shadows and a fill light; Whitted tracing, so glass and
/// mirrors spawn the secondary rays of the thesis's scenes. The mesh's <see cref="Mesh.TriangleTest"/>
/// is read at each build.
/// </summary>
public sealed class TriangleTestScene : SceneDescription
{
    private readonly string _name;
    private readonly string _description;

    public TriangleTestScene(string name, string description, Mesh mesh, string thesisScene, int thesisTriangles)
    {
        _name = name;
        _description = description;
        Mesh = mesh;
        ThesisScene = thesisScene;
        ThesisTriangles = thesisTriangles;
    }

    public override string Name => _name;
    public override string Description => _description;
    public override int DefaultWidth => 320;
    public override int DefaultHeight => 240;
    public override int DefaultSamples => 1;
    public override int DefaultMaxDepth => 6;

    public Mesh Mesh { get; }

    /// <summary>The scene of Figure 7-8 this one stands for, and its triangle count in Table 7-3.</summary>
    public string ThesisScene { get; }

    public int ThesisTriangles { get; }

    /// <summary>Camera direction from the mesh's centre: degrees from +z towards +x, and above the horizon.</summary>
    public double Azimuth { get; init; } = 30;

    public double Elevation { get; init; } = 20;

    /// <summary>The BIH over the mesh's triangles, as the last build made it.</summary>
    public BoundingIntervalHierarchy? Hierarchy { get; private set; }

    protected override void Populate(World world)
    {
        var vp = world.ViewPlane;
        var (centre, radius) = MeshStudioScene.BoundingSphere(Mesh);
        world.BackgroundColor = new RGBColor(0.55, 0.62, 0.72);
        world.AmbientLight = new AmbientLight(0.3);
        var floor = Mesh.Bounds.Min.y - 1e-3 * radius;
        var checker = TextureFactory.PlaneChecker(radius / 2, new RGBColor(0.85, 0.83, 0.78), new RGBColor(0.35, 0.37, 0.42));
        world.Add(new Plane(new Point3D(0, floor, 0), new Normal3D(0, 1, 0)) { Material = MaterialFactory.Matte(checker, 0.35, 0.7) });

        Hierarchy = new BoundingIntervalHierarchy(Mesh.CreateTriangles(smooth: true));
        world.Add(Hierarchy);

        world.Add(LightFactory.Point(centre + 6 * radius * MeshStudioScene.Direction(Azimuth - 50, 55), 1.0));
        world.Add(new DirectionalLight(MeshStudioScene.Direction(Azimuth + 70, 25), 0.35) { CastsShadows = false });
        var eye = centre + MeshStudioScene.FittedDistance(radius, vp.HorizontalResolution, vp.VerticalResolution) * MeshStudioScene.Direction(Azimuth, Elevation);
        world.Camera = CameraFactory.Pinhole(eye, centre, MeshStudioScene.HorizontalFieldOfViewDegrees, vp);
        world.Integrator = new WhittedIntegrator(world);
    }

    /// <summary>Gives the mesh a material and returns the scene, for building the catalogue in one expression.</summary>
    public TriangleTestScene With(Material material)
    {
        Mesh.Material = material;
        return this;
    }
}
