using System.Globalization;
using System.Text;
using RayTracer.Acceleration;
using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry;
using RayTracer.Geometry.Meshes;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Kernels;
using RayTracer.Lights;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Meshes;

/// <summary>
/// Triangle meshes in the three acceleration structures: a smooth-shaded displaced sphere in a BVH, the
/// same mesh flat-shaded in a regular grid, and an icosahedron read from PLY text in a BIH.
/// </summary>
public sealed class MeshesScene : SceneDescription
{
    public override string Name => "meshes";
    public override string Description => "Smooth and flat triangle meshes (BVH, regular grid) and a PLY-read icosahedron (BIH).";

    /// <summary>Triangles of each displaced sphere.</summary>
    public int Triangles { get; init; } = 20_000;

    /// <summary>An icosahedron in ASCII PLY, as it would come from a file.</summary>
    public static string IcosahedronPly()
    {
        var t = (1 + Math.Sqrt(5)) / 2;
        double[][] v =
        [
            [-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t],
            [0, -1, -t], [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1],
        ];
        int[][] f =
        [
            [0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8],
            [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1],
        ];
        var text = new StringBuilder();
        text.Append("ply\nformat ascii 1.0\ncomment icosahedron\n");
        text.Append(CultureInfo.InvariantCulture, $"element vertex {v.Length}\nproperty float x\nproperty float y\nproperty float z\n");
        text.Append(CultureInfo.InvariantCulture, $"element face {f.Length}\nproperty list uchar int vertex_indices\nend_header\n");
        foreach (var p in v)
            text.Append(CultureInfo.InvariantCulture, $"{p[0]} {p[1]} {p[2]}\n");
        foreach (var face in f)
            text.Append(CultureInfo.InvariantCulture, $"3 {face[0]} {face[1]} {face[2]}\n");
        return text.ToString();
    }

    /// <summary>
    /// The same mesh with every triangle wound so its geometric normal points away from the origin; shading
    /// treats the normal side as the outside, so a closed mesh must be wound outwards.
    /// </summary>
    public static Mesh OutwardFacing(Mesh mesh)
    {
        var indices = (int[])mesh.Indices.Clone();
        for (var i = 0; i + 2 < indices.Length; i += 3)
        {
            Point3D a = mesh.Vertices[indices[i]], b = mesh.Vertices[indices[i + 1]], c = mesh.Vertices[indices[i + 2]];
            var normal = TriangleNormal.Of(a, b, c);
            var centre = (a.ToVector() + b.ToVector() + c.ToVector()) / 3;
            if (normal.Dot(centre) < 0)
                (indices[i + 1], indices[i + 2]) = (indices[i + 2], indices[i + 1]);
        }
        return new Mesh(mesh.Vertices, indices);
    }

    protected override void Populate(World world)
    {
        world.BackgroundColor = new RGBColor(0.12, 0.13, 0.16);
        world.AmbientLight = new AmbientLight(0.4);
        world.Add(new Plane(new Point3D(0, -1.05, 0), new Normal3D(0, 1, 0))
        {
            Material = MaterialFactory.Matte(TextureFactory.PlaneChecker(0.6, new RGBColor(0.8, 0.8, 0.8), new RGBColor(0.45, 0.45, 0.5))),
        });

        var smooth = OutwardFacing(ThroughputReport.DisplacedSphere(Triangles));
        smooth.Material = MaterialFactory.Plastic(new RGBColor(0.9, 0.55, 0.2), 60);
        world.Add(new Instance(new Bvh(smooth.CreateTriangles(smooth: true))).Translate(-2.3, 0, 0));

        var flat = OutwardFacing(ThroughputReport.DisplacedSphere(Triangles / 8));
        flat.Material = MaterialFactory.Plastic(new RGBColor(0.3, 0.6, 0.9), 60);
        world.Add(new RegularGrid(flat.CreateTriangles(smooth: false)));

        using var stream = new MemoryStream(Encoding.ASCII.GetBytes(IcosahedronPly()));
        var icosahedron = PlyReader.Read(stream, "icosahedron.ply");
        icosahedron.Material = MaterialFactory.Shiny(new RGBColor(0.4, 0.85, 0.4));
        world.Add(new Instance(new BoundingIntervalHierarchy(icosahedron.CreateTriangles(smooth: false))).Scale(0.55).RotateY(0.4).Translate(2.3, 0, 0));

        world.Add(LightFactory.Point(new Point3D(-3, 6, 7), 1.2));
        world.Add(LightFactory.Directional(new Vector3D(4, 3, 2), 0.5));
        world.Camera = CameraFactory.Pinhole(new Point3D(0, 1.8, 7), new Point3D(0, -0.1, 0), 55, world.ViewPlane);
        world.Integrator = new WhittedIntegrator(world);
    }
}
