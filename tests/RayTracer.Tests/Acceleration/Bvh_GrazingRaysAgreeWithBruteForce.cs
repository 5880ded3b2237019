using RayTracer.Acceleration;
using RayTracer.Geometry;
using RayTracer.Geometry.Meshes;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Acceleration;

/// <summary>
/// Rays that touch node boxes exactly, where a box test that is not conservative would skip a node the
/// ray hits: the scene is unit cubes on a lattice (boxes with shared faces, coplanar triangles in
/// different leaves, flat boxes of single triangles), and the rays aim at corners, at points on edges and
/// face diagonals and inside faces, with distance limits just above and exactly at the nearest hit. At
/// unit scale, at 0.1 (planes that are not floats), and near 1e-30 and 1e30; a few rays lie in a face plane.
/// (Before the fixes in <see cref="Bvh"/>'s box test, rays along a face at a cube's edge, with the origin on
/// the box's far plane, and hits on box faces at 1e30 and 1e-30 with the limit just above them, were missed.)
/// </summary>
public class Bvh_GrazingRaysAgreeWithBruteForce
{
    public static TheoryData<double, int, int> Scales
    {
        get
        {
            var data = new TheoryData<double, int, int>();
            foreach (int width in BvhWidths.Available)
            {
                foreach (var (scale, leafSize) in (ReadOnlySpan<(double, int)>)[(1, 1), (1, 4), (0.1, 1), (1e-30, 1), (1e-30, 4), (1e30, 1), (1e30, 4)])
                    data.Add(scale, leafSize, width);
            }

            return data;
        }
    }

    /// <summary>Unit cubes on a 3 × 3 × 3 lattice, about two in three present, each of 12 triangles.</summary>
    private static Mesh Cubes(SeededRandom random, double scale)
    {
        var vertices = new List<Point3D>();
        var indices = new List<int>();
        int[][] faces = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]];
        for (int i = 0; i < 27; i++)
        {
            if (random.NextDouble() < 0.35)
                continue;
            int first = vertices.Count;
            for (int c = 0; c < 8; c++)
                vertices.Add(new Point3D(scale * (i % 3 + (c & 1)), scale * (i / 3 % 3 + ((c >> 1) & 1)), scale * (i / 9 + ((c >> 2) & 1))));
            foreach (var f in faces)
                indices.AddRange([first + f[0], first + f[1], first + f[2], first + f[0], first + f[2], first + f[3]]);
        }

        return new Mesh([.. vertices], [.. indices]);
    }

    private static void AssertAgrees(Bvh bvh, GeometricObject[] triangles, in Ray ray)
    {
        double expected = BruteForce.Nearest(triangles, ray);
        Assert.Equal(expected, Nearest(bvh, ray, double.PositiveInfinity));
        if (!double.IsFinite(expected))
            return;

        // Limits at and just above the hit: the hit counts only strictly before the limit.
        double above = Math.BitIncrement(expected);
        Assert.Equal(expected, Nearest(bvh, ray, above));
        Assert.Equal(double.PositiveInfinity, Nearest(bvh, ray, expected));
        Assert.True(bvh.IntersectAny(ray, above));
        Assert.False(bvh.IntersectAny(ray, expected));
    }

    private static double Nearest(Bvh bvh, in Ray ray, double tMax) =>
        bvh.IntersectNearest(ray, tMax, out double t, out _) ? t : double.PositiveInfinity;

    [Theory]
    [MemberData(nameof(Scales))]
    public void Rays_touching_boxes_exactly_match_brute_force(double scale, int leafSize, int width)
    {
        var random = new SeededRandom(2900 + (ulong)leafSize);
        var mesh = Cubes(random, scale);
        var triangles = mesh.CreateTriangles(smooth: false);
        var bvh = new Bvh(triangles, leafSize, BvhBuilder.Parallelism.Default, width);
        int hits = 0;
        for (int n = 0; n < 1200; n++)
        {
            int f = random.NextInt(mesh.TriangleCount);
            Point3D a = mesh.Vertices[mesh.Indices[3 * f]], b = mesh.Vertices[mesh.Indices[3 * f + 1]], c = mesh.Vertices[mesh.Indices[3 * f + 2]];
            double s = random.NextDouble();
            var target = (n % 4) switch
            {
                0 => a,                                // a corner
                1 => a + s * (b - a),                  // on a cube edge
                2 => a + s * (c - a),                  // on the face's diagonal, the edge two triangles share
                _ => a + s * (b - a) + (1 - s) * random.NextDouble() * (c - b), // inside the face
            };
            var origin = new Point3D(scale * random.NextDouble(-2, 5), scale * random.NextDouble(-2, 5), scale * random.NextDouble(-2, 5));
            if (n % 16 == 15)
            {
                // In the plane of a face the target lies on, along an axis of that plane.
                var normal = Vector3D.Cross(b - a, c - a);
                int axis = Math.Abs(normal.x) > 0 ? 0 : Math.Abs(normal.y) > 0 ? 1 : 2;
                origin = axis switch
                {
                    0 => new Point3D(target.x, origin.y, target.z),
                    1 => new Point3D(origin.x, target.y, target.z),
                    _ => new Point3D(target.x, origin.y, target.z),
                };
            }

            // Every other ray in a face plane turned round: its zero direction component becomes −0.
            var direction = n % 32 == 31 ? -(target - origin) : target - origin;
            var ray = new Ray(origin, direction, 1e-9);
            AssertAgrees(bvh, triangles, ray);
            hits += double.IsFinite(BruteForce.Nearest(triangles, ray)) ? 1 : 0;
        }

        Assert.True(hits > 600, $"only {hits} hits");
    }
}
