using RayTracer.Acceleration;
using RayTracer.Geometry;
using RayTracer.Geometry.Meshes;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Acceleration;

/// <summary>
/// A tree with many full wide nodes (small scattered triangles, one per leaf: an eighth of the nodes or
/// more are full, the upper ones), and a ray aimed at every triangle, from outside the cloud and from
/// inside it (where a node's children are entered several at a time and ordered by distance): the nearest
/// hit must be brute force's, to the last bit, and the any hit must see it. A traversal that skipped a child lane, read the wrong lane's reference or dropped an
/// entered child while ordering would lose the triangles under it.
/// </summary>
public class Bvh_EveryChildOfAWideNodeIsVisited
{
    public static TheoryData<int> Widths => [.. BvhWidths.Available];

    private static Point3D RandomPoint(SeededRandom random, double r) =>
        new(random.NextDouble(-r, r), random.NextDouble(-r, r), random.NextDouble(-r, r));

    [Theory]
    [MemberData(nameof(Widths))]
    public void A_ray_at_every_triangle_of_full_nodes_finds_brute_force_hit(int width)
    {
        var random = new SeededRandom(2907);
        const int count = 1500;
        var vertices = new Point3D[3 * count];
        var centroids = new Point3D[count];
        for (int i = 0; i < count; i++)
        {
            var c = RandomPoint(random, 5);
            for (int k = 0; k < 3; k++)
                vertices[3 * i + k] = c + (RandomPoint(random, 0.3) - Point3D.Origin);
            centroids[i] = Point3D.Origin + ((vertices[3 * i] - Point3D.Origin + (vertices[3 * i + 1] - Point3D.Origin) + (vertices[3 * i + 2] - Point3D.Origin)) / 3);
        }

        GeometricObject[] triangles = new Mesh(vertices, [.. Enumerable.Range(0, vertices.Length)]).CreateTriangles(smooth: false);
        var bvh = new Bvh(triangles, 1, BvhBuilder.Parallelism.Default, width);
        Assert.Equal(width, bvh.Width);
        Assert.True(bvh.NodesWithChildren(width) >= bvh.NodeCount / 8, $"{bvh.NodesWithChildren(width)} of {bvh.NodeCount} nodes full");

        for (int i = 0; i < count; i++)
        {
            var origin = RandomPoint(random, i % 2 == 0 ? 12 : 4);
            var ray = new Ray(origin, centroids[i] - origin);
            double expected = BruteForce.Nearest(triangles, ray);
            Assert.True(double.IsFinite(expected)); // the centroid lies on triangle i at t = 1, or something nearer is hit
            Assert.True(bvh.IntersectNearest(ray, double.PositiveInfinity, out double t, out int primitive));
            Assert.Equal(expected, t);
            Assert.True(bvh.GetPrimitive(primitive).Intersect(ray, out double tp) && tp == expected);
            Assert.True(bvh.IntersectAny(ray, Math.BitIncrement(expected)));
            Assert.False(bvh.IntersectAny(ray, expected));
        }
    }
}
