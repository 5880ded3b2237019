using RayTracer.Acceleration;
using RayTracer.Geometry;
using RayTracer.Geometry.Meshes;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Acceleration;

/// <summary>
/// Meshes only, so every leaf of the BVH tests its triangles in four-lane groups (several groups per
/// leaf when leaves hold more than four): nearest hits equal brute force's to the last bit, any hit
/// agrees with the nearest hit lying within the distance, on random rays and on rays aimed exactly at
/// vertices and edges.
/// </summary>
public class Bvh_MeshAgreesWithBruteForce
{
    public static TheoryData<int, int> LeafSizesAndWidths
    {
        get
        {
            var data = new TheoryData<int, int>();
            foreach (int width in BvhWidths.Available)
            {
                foreach (int leafSize in (int[])[1, 3, 4, 8, 12])
                    data.Add(leafSize, width);
            }

            return data;
        }
    }

    public static TheoryData<int> Widths => [.. BvhWidths.Available];

    private static Point3D RandomPoint(SeededRandom random, double r) =>
        new(random.NextDouble(-r, r), random.NextDouble(-r, r), random.NextDouble(-r, r));

    /// <summary>A triangle soup of small and large triangles, plus a closed displaced sphere sharing edges and vertices.</summary>
    private static (GeometricObject[] Triangles, Mesh Soup) RandomMeshes(ulong seed, int soupTriangles)
    {
        var random = new SeededRandom(seed);
        var vertices = new Point3D[3 * soupTriangles];
        for (int i = 0; i < soupTriangles; i++)
        {
            var c = RandomPoint(random, 6);
            double size = random.NextDouble() < 0.1 ? 3 : 0.5;
            for (int k = 0; k < 3; k++)
                vertices[3 * i + k] = c + (RandomPoint(random, size) - Point3D.Origin);
        }

        var soup = new Mesh(vertices, [.. Enumerable.Range(0, vertices.Length)]);
        var sphere = ThroughputReport.DisplacedSphere(800);
        return ([.. soup.CreateTriangles(smooth: false), .. sphere.CreateTriangles(smooth: false)], soup);
    }

    private static void AssertAgrees(Bvh bvh, GeometricObject[] triangles, in Ray ray, double tMax)
    {
        double expected = BruteForce.Nearest(triangles, ray);
        bool hit = bvh.IntersectNearest(ray, double.PositiveInfinity, out double t, out int primitive);
        Assert.Equal(double.IsFinite(expected), hit);
        if (hit)
        {
            Assert.Equal(expected, t);
            Assert.True(bvh.GetPrimitive(primitive).Intersect(ray, out double tp) && tp == expected);
        }

        Assert.Equal(expected < tMax, bvh.IntersectAny(ray, tMax));
    }

    [Theory]
    [MemberData(nameof(LeafSizesAndWidths))]
    public void Nearest_and_any_hit_match_brute_force_on_random_rays_and_on_vertices_and_edges(int leafSize, int width)
    {
        var (triangles, soup) = RandomMeshes(290 + (ulong)leafSize, 1200);
        var bvh = new Bvh(triangles, leafSize, BvhBuilder.Parallelism.Default, width);
        var random = new SeededRandom(291);
        for (int n = 0; n < 2500; n++)
        {
            var origin = RandomPoint(random, n % 2 == 0 ? 5 : 20);
            int f = random.NextInt(soup.TriangleCount);
            Point3D a = soup.Vertices[soup.Indices[3 * f]], b = soup.Vertices[soup.Indices[3 * f + 1]];
            var target = (n % 4) switch
            {
                0 => a,                        // a vertex
                1 => a + 0.5 * (b - a),        // an edge's midpoint
                2 => RandomPoint(random, 6),
                _ => new Point3D(random.NextDouble(-1.1, 1.1), random.NextDouble(-1.1, 1.1), 0), // the sphere
            };
            AssertAgrees(bvh, triangles, new Ray(origin, target - origin), random.NextDouble(0.05, 1.5));
        }
    }

    [Theory]
    [MemberData(nameof(Widths))]
    public void Rays_along_edges_and_from_vertices_match_brute_force(int width)
    {
        var (triangles, soup) = RandomMeshes(292, 300);
        var bvh = new Bvh(triangles, 4, BvhBuilder.Parallelism.Default, width);
        for (int f = 0; f < soup.TriangleCount; f++)
        {
            Point3D a = soup.Vertices[soup.Indices[3 * f]], b = soup.Vertices[soup.Indices[3 * f + 1]];
            AssertAgrees(bvh, triangles, new Ray(a + 2 * (a - b), b - a), 2.5); // along the edge's line, through it
            AssertAgrees(bvh, triangles, new Ray(a, b - a) { tMin = 1e-9 }, 0.5); // leaving a vertex along an edge
        }
    }

    [Theory]
    [MemberData(nameof(Widths))]
    public void Empty_and_single_triangle_meshes(int width)
    {
        var ray = new Ray(new Point3D(0.2, 0.2, 5), new Vector3D(0, 0, -1));
        var empty = new Bvh(new Mesh([], []).CreateTriangles(smooth: false), 4, BvhBuilder.Parallelism.Default, width);
        Assert.False(empty.IntersectNearest(ray, double.PositiveInfinity, out _, out _));
        Assert.False(empty.IntersectAny(ray, double.PositiveInfinity));

        var one = new Mesh([new Point3D(0, 0, 0), new Point3D(1, 0, 0), new Point3D(0, 1, 0)], [0, 1, 2]).CreateTriangles(smooth: false);
        var bvh = new Bvh(one, 4, BvhBuilder.Parallelism.Default, width);
        Assert.True(bvh.IntersectNearest(ray, double.PositiveInfinity, out double t, out int primitive));
        Assert.Equal(5, t);
        Assert.Same(one[0], bvh.GetPrimitive(primitive));
        Assert.True(bvh.IntersectAny(ray, 5.5));
        Assert.False(bvh.IntersectAny(ray, 5)); // the hit must lie strictly before the distance
        Assert.False(bvh.IntersectNearest(new Ray(new Point3D(0.6, 0.6, 5), new Vector3D(0, 0, -1)), double.PositiveInfinity, out _, out _));
    }
}
