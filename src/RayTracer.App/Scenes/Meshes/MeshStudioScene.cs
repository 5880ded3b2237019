using RayTracer.Acceleration;
using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry.Meshes;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Meshes;

/// <summary>
/// Any mesh in a neutral studio, so a user can look at their own file without writing a scene: the camera
/// sees the whole mesh from a three-quarter view above, a ground plane lies just under it, a key light casts
/// shadows and a fill light softens them. The mesh is light gray matte, lit alike on both faces. Y is up.
/// </summary>
public sealed class MeshStudioScene : SceneDescription
{
    public static readonly RGBColor Background = new(0.16, 0.17, 0.2);
    public static readonly RGBColor GroundColor = new(0.5, 0.47, 0.42);
    public static readonly RGBColor MeshColor = new(0.8, 0.8, 0.78);

    public const double HorizontalFieldOfViewDegrees = 40;

    /// <summary>Distance from the view's edges: the mesh's bounding sphere fills at most 1 / Margin of the narrower half-angle.</summary>
    public const double Margin = 1.15;

    /// <summary>Where the camera stands, seen from above: turned from +z towards +x, and raised above the horizon.</summary>
    public const double AzimuthDegrees = 35, ElevationDegrees = 25;

    private readonly Mesh _mesh;
    private readonly string _fileName;

    public MeshStudioScene(Mesh mesh, string fileName)
    {
        if (mesh.TriangleCount == 0)
            throw new ArgumentException($"{fileName} has no triangles to render.", nameof(mesh));
        _mesh = mesh;
        _fileName = fileName;
    }

    public override string Name => "mesh";
    public override string Description => $"{_fileName} in a studio: fitted camera, ground, key and fill lights.";

    /// <summary>
    /// A sphere around every vertex, centred on the bounding box (radius 1 for a single point). Its radius is
    /// the farthest vertex, not the box's half diagonal, so flat or thin meshes are not framed too small.
    /// </summary>
    public static (Point3D Centre, double Radius) BoundingSphere(Mesh mesh)
    {
        var box = mesh.Bounds;
        var centre = Point3D.Lerp(box.Min, box.Max, 0.5);
        var radius = mesh.Vertices.Max(v => v.Distance(centre));
        return (centre, radius > 0 ? radius : 1.0);
    }

    /// <summary>Unit vector at <paramref name="azimuthDegrees"/> from +z towards +x and <paramref name="elevationDegrees"/> above the horizon.</summary>
    public static Vector3D Direction(double azimuthDegrees, double elevationDegrees)
    {
        var azimuth = MathConstants.ToRadians(azimuthDegrees);
        var elevation = MathConstants.ToRadians(elevationDegrees);
        return new Vector3D(Math.Sin(azimuth) * Math.Cos(elevation), Math.Sin(elevation), Math.Cos(azimuth) * Math.Cos(elevation));
    }

    /// <summary>
    /// Distance from the centre at which a sphere of <paramref name="radius"/> fits the view with the margin,
    /// for an image <paramref name="width"/> by <paramref name="height"/> pixels.
    /// </summary>
    public static double FittedDistance(double radius, int width, int height)
    {
        var halfWidth = MathConstants.ToRadians(HorizontalFieldOfViewDegrees) / 2;
        var halfHeight = Math.Atan(Math.Tan(halfWidth) * height / width);
        return Margin * radius / Math.Sin(Math.Min(halfWidth, halfHeight));
    }

    protected override void Populate(World world)
    {
        var vp = world.ViewPlane;
        var (centre, radius) = BoundingSphere(_mesh);
        world.BackgroundColor = Background;
        world.AmbientLight = new AmbientLight(0.35);

        // Just under the lowest vertex, so a mesh standing on its base neither floats nor fights the ground.
        var groundHeight = _mesh.Bounds.Min.y - 1e-3 * radius;
        world.Add(new Plane(new Point3D(0, groundHeight, 0), new Normal3D(0, 1, 0)) { Material = MaterialFactory.Matte(GroundColor, 0.3, 0.7) });

        _mesh.Material = new TwoSided(MaterialFactory.Matte(MeshColor, 0.3, 0.75));
        world.Add(new Bvh(_mesh.CreateTriangles(smooth: _mesh.Normals is not null)));

        // Key light high on the camera's left, fill light low on its right; only the key casts shadows.
        world.Add(LightFactory.Point(centre + 6 * radius * Direction(AzimuthDegrees - 50, 55), 0.95));
        world.Add(new DirectionalLight(Direction(AzimuthDegrees + 70, 20), 0.3) { CastsShadows = false });

        var eye = centre + FittedDistance(radius, vp.HorizontalResolution, vp.VerticalResolution) * Direction(AzimuthDegrees, ElevationDegrees);
        world.Camera = CameraFactory.Pinhole(eye, centre, HorizontalFieldOfViewDegrees, vp);
        world.Integrator = new RayCastIntegrator(world);
    }
}
