using RayTracer.Acceleration;
using RayTracer.Geometry;
using RayTracer.Geometry.Meshes;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Acceleration;

/// <summary>
/// The build shares work among threads from sizes that small meshes never reach; here those sizes are set
/// so low that every parallel path runs (subtrees handed to other threads, ranges binned in slices whose
/// bins are merged, loops split into chunks). The tree must not depend on it: the same node counts and the
/// same primitive for every ray as a build on one thread, at brute force's distance.
/// </summary>
public class Bvh_ParallelBuildMatchesSerial
{
    private static readonly BvhBuilder.Parallelism Everywhere = new(Subtrees: 2, Binning: 8, Chunk: 16);

    public static TheoryData<int, int> LeafSizes
    {
        get
        {
            var data = new TheoryData<int, int>();
            foreach (int width in BvhWidths.Available)
            {
                foreach (int leafSize in (int[])[1, 4, 8])
                    data.Add(leafSize, width);
            }

            return data;
        }
    }

    public static TheoryData<int> Widths => [.. BvhWidths.Available];

    private static Point3D RandomPoint(SeededRandom random, double r) =>
        new(random.NextDouble(-r, r), random.NextDouble(-r, r), random.NextDouble(-r, r));

    /// <summary>Small and large triangles at random, the kind of soup that makes uneven splits.</summary>
    private static GeometricObject[] Soup(ulong seed, int count)
    {
        var random = new SeededRandom(seed);
        var vertices = new Point3D[3 * count];
        for (int i = 0; i < count; i++)
        {
            var c = RandomPoint(random, 6);
            double size = random.NextDouble() < 0.1 ? 3 : 0.4;
            for (int k = 0; k < 3; k++)
                vertices[3 * i + k] = c + (RandomPoint(random, size) - Point3D.Origin);
        }

        return new Mesh(vertices, [.. Enumerable.Range(0, vertices.Length)]).CreateTriangles(smooth: false);
    }

    /// <summary>
    /// Tilted triangles of growing size, every other one turned a quarter: different shapes, boxes
    /// [−s, s]² × [−h, h] all centred on the origin. (Not coplanar: where coplanar triangles overlap,
    /// their computed distances differ in the last bits, and a box whose entry equals the plane's exact
    /// distance can be passed over for a triangle inside it that rounds a little nearer.)
    /// </summary>
    private static GeometricObject[] SameCentroid(int count)
    {
        var vertices = new Point3D[3 * count];
        for (int i = 0; i < count; i++)
        {
            double s = 0.5 + (double)i / count, h = 0.2 * s;
            Point3D[] corners = i % 2 == 0
                ? [new(-s, -s, -h), new(s, -s, h), new(0, s, 0)]
                : [new(-s, -s, h), new(-s, s, -h), new(s, 0, 0)];
            corners.CopyTo(vertices, 3 * i);
        }

        return new Mesh(vertices, [.. Enumerable.Range(0, vertices.Length)]).CreateTriangles(smooth: false);
    }

    private static void AssertSameTrees(GeometricObject[] triangles, int leafSize, int width, Func<SeededRandom, Ray> rays, int rayCount)
    {
        var serial = new Bvh(triangles, leafSize, BvhBuilder.Parallelism.None, width);
        var parallel = new Bvh(triangles, leafSize, Everywhere, width);
        Assert.Equal(serial.BinaryNodeCount, parallel.BinaryNodeCount);
        Assert.Equal(serial.NodeCount, parallel.NodeCount);

        var random = new SeededRandom(301);
        for (int n = 0; n < rayCount; n++)
        {
            var ray = rays(random);
            double expected = BruteForce.Nearest(triangles, ray);
            bool hit = parallel.IntersectNearest(ray, double.PositiveInfinity, out double t, out int primitive);
            Assert.Equal(double.IsFinite(expected), hit);
            Assert.Equal(serial.IntersectNearest(ray, double.PositiveInfinity, out double ts, out int primitiveSerial), hit);
            if (hit)
            {
                Assert.Equal(expected, t);
                Assert.Equal(ts, t);
                Assert.Same(serial.GetPrimitive(primitiveSerial), parallel.GetPrimitive(primitive));
            }

            Assert.Equal(expected < 4, parallel.IntersectAny(ray, 4));
        }
    }

    [Theory]
    [MemberData(nameof(LeafSizes))]
    public void A_random_soup_gives_the_serial_tree_and_brute_force_hits(int leafSize, int width)
    {
        var triangles = Soup(300 + (ulong)leafSize, 1500);
        AssertSameTrees(triangles, leafSize, width, random =>
        {
            var origin = RandomPoint(random, 15);
            return new Ray(origin, RandomPoint(random, 5) - origin);
        }, 400);
    }

    [Theory]
    [MemberData(nameof(LeafSizes))]
    public void Triangles_sharing_one_centroid_are_split_in_halves_alike(int leafSize, int width)
    {
        var triangles = SameCentroid(300);
        AssertSameTrees(triangles, leafSize, width, random =>
        {
            var origin = new Point3D(random.NextDouble(-1.5, 1.5), random.NextDouble(-1.5, 1.5), 3);
            return new Ray(origin, new Vector3D(random.NextDouble(-0.1, 0.1), random.NextDouble(-0.1, 0.1), -1));
        }, 300);
    }

    [Theory]
    [MemberData(nameof(Widths))]
    public void Duplicated_triangles_give_the_serial_tree(int width)
    {
        var one = Soup(302, 1)[0] as MeshTriangle;
        var mesh = new Mesh([one!.V0, one.V1, one.V2], [.. Enumerable.Repeat(new[] { 0, 1, 2 }, 200).SelectMany(i => i)]);
        AssertSameTrees(mesh.CreateTriangles(smooth: false), 4, width, random =>
        {
            var target = one.V0 + (0.3 * (one.V1 - one.V0)) + (0.3 * (one.V2 - one.V0));
            var origin = RandomPoint(random, 10);
            return new Ray(origin, target - origin);
        }, 50);
    }

    [Theory]
    [MemberData(nameof(Widths))]
    public void One_triangle_and_none_build_with_every_path_enabled(int width)
    {
        var ray = new Ray(new Point3D(0.2, 0.2, 5), new Vector3D(0, 0, -1));
        var empty = new Bvh(new Mesh([], []).CreateTriangles(smooth: false), 4, Everywhere, width);
        Assert.Equal(0, empty.NodeCount);
        Assert.False(empty.IntersectNearest(ray, double.PositiveInfinity, out _, out _));

        var one = new Mesh([new Point3D(0, 0, 0), new Point3D(1, 0, 0), new Point3D(0, 1, 0)], [0, 1, 2]).CreateTriangles(smooth: false);
        var bvh = new Bvh(one, 1, Everywhere, width);
        Assert.True(bvh.IntersectNearest(ray, double.PositiveInfinity, out double t, out int primitive));
        Assert.Equal(5, t);
        Assert.Same(one[0], bvh.GetPrimitive(primitive));
    }
}
