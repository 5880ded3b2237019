using RayTracer.Acceleration;
using RayTracer.Geometry.Meshes;
using RayTracer.Geometry.Solvers;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Scenes.Triangles;
using RayTracer.Tracing;

namespace RayTracer.Tests.Geometry.Solvers;

/// <summary>
/// The four ray–triangle tests find the same nearest hit (triangle, t, barycentrics) on random rays, on
/// random triangle soups and on the bunny, except where a hit lies within 1e-9 (in barycentric
/// coordinates) of an edge, where rounding may pick the neighbour or nothing.
/// </summary>
[Collection(TriangleTestCollection.Name)]
public sealed class TriangleTests_Agree
{
    private const double Tolerance = 1e-9;

    private static readonly TriangleTest[] Others = [TriangleTest.Algebraic, TriangleTest.Plucker, TriangleTest.PluckerEdges];

    private readonly record struct NearestHit(int Triangle, double T, double Beta, double Gamma)
    {
        public double EdgeDistance => Math.Min(Math.Min(Beta, Gamma), 1 - Beta - Gamma);
    }

    private static NearestHit? Nearest(Mesh mesh, TriangleTest test, in Ray ray)
    {
        mesh.TriangleTest = test;
        NearestHit? best = null;
        foreach (var triangle in mesh.CreateTriangles(smooth: false))
        {
            if (triangle.Solve(ray, out var t, out var beta, out var gamma) && (best is null || t < best.Value.T))
                best = new NearestHit(triangle.Index, t, beta, gamma);
        }

        return best;
    }

    /// <summary>Compares every other test with Möller–Trumbore; returns the disagreements that lie within the tolerance of an edge.</summary>
    private static int CompareOnRays(Mesh mesh, IEnumerable<Ray> rays)
    {
        var nearEdge = 0;
        var hits = 0;
        foreach (var ray in rays)
        {
            var reference = Nearest(mesh, TriangleTest.MollerTrumbore, ray);
            if (reference is not null)
                hits++;
            foreach (var test in Others)
            {
                var other = Nearest(mesh, test, ray);
                var agree = (reference, other) switch
                {
                    (null, null) => true,
                    ({ } a, { } b) => a.Triangle == b.Triangle && Close(a.T, b.T) && Close(a.Beta, b.Beta) && Close(a.Gamma, b.Gamma),
                    _ => false,
                };
                if (agree)
                    continue;
                var nearAnEdge = reference is { EdgeDistance: < Tolerance } || other is { EdgeDistance: < Tolerance }
                    || (reference is { } r && other is { } o && Close(r.T, o.T)); // a shared edge or vertex: same point, neighbouring triangle
                Assert.True(nearAnEdge, $"{test} disagrees with Möller–Trumbore away from any edge on {ray}: {reference} against {other}");
                nearEdge++;
            }
        }

        Assert.True(hits > 0, "no ray hit the mesh; the comparison would be empty");
        return nearEdge;
    }

    private static bool Close(double a, double b) => Math.Abs(a - b) <= Tolerance * (1 + Math.Abs(a));

    private static Mesh RandomSoup(int triangles, ulong seed)
    {
        var random = new SeededRandom(seed);
        var vertices = new Point3D[3 * triangles];
        for (var i = 0; i < triangles; i++)
        {
            var centre = new Point3D(random.NextDouble(-3, 3), random.NextDouble(-3, 3), random.NextDouble(-3, 3));
            for (var k = 0; k < 3; k++)
                vertices[3 * i + k] = centre + new Vector3D(random.NextDouble(-1, 1), random.NextDouble(-1, 1), random.NextDouble(-1, 1));
        }

        return new Mesh(vertices, [.. Enumerable.Range(0, vertices.Length)]);
    }

    private static IEnumerable<Ray> RandomRays(int count, ulong seed, double spread)
    {
        var random = new SeededRandom(seed);
        for (var i = 0; i < count; i++)
        {
            var origin = new Point3D(random.NextDouble(-spread, spread), random.NextDouble(-spread, spread), random.NextDouble(-spread, spread));
            var target = new Point3D(random.NextDouble(-3, 3), random.NextDouble(-3, 3), random.NextDouble(-3, 3));
            yield return new Ray(origin, target - origin);
        }
    }

    [Fact]
    public void Tests_agree_on_random_rays_against_a_random_soup()
    {
        var nearEdge = CompareOnRays(RandomSoup(60, 3), RandomRays(400, 5, 8));
        Assert.True(nearEdge <= 3, $"{nearEdge} near-edge disagreements out of 1200 comparisons");
    }

    [Fact]
    public void Tests_agree_on_the_bunny_including_rays_aimed_at_its_vertices()
    {
        var bunny = TriangleTestScenes.ReadBunny();
        var random = new SeededRandom(11);
        var box = bunny.Bounds;
        var rays = new List<Ray>();
        for (var i = 0; i < 60; i++)
        {
            var origin = new Point3D(random.NextDouble(-15, 15), random.NextDouble(-5, 20), random.NextDouble(-15, 15));
            var target = new Point3D(random.NextDouble(box.Min.x, box.Max.x), random.NextDouble(box.Min.y, box.Max.y), random.NextDouble(box.Min.z, box.Max.z));
            rays.Add(new Ray(origin, target - origin));
            // Aimed exactly at a vertex: the hit lies on the edges of every triangle around it.
            var vertex = bunny.Vertices[random.NextInt(bunny.Vertices.Length)];
            rays.Add(new Ray(origin, vertex - origin));
        }

        var nearEdge = CompareOnRays(bunny, rays);
        // Only the 60 rays through vertices can hit within 1e-9 of an edge; at most one disagreement per test each.
        Assert.True(nearEdge <= 3 * 60, $"{nearEdge} near-edge disagreements");
    }

    [Fact]
    public void Barycentrics_rebuild_the_hit_point_for_every_test()
    {
        Point3D v0 = new(0.2, -0.1, 1), v1 = new(2, 0.3, 0.5), v2 = new(0.4, 1.7, -0.2);
        var mesh = new Mesh([v0, v1, v2], [0, 1, 2]);
        var ray = new Ray(new Point3D(0.6, 0.5, 4), new Vector3D(0.05, 0.02, -1));
        foreach (var test in Enum.GetValues<TriangleTest>())
        {
            mesh.TriangleTest = test;
            Assert.True(mesh.CreateTriangles(smooth: false)[0].Solve(ray, out var t, out var beta, out var gamma), test.ToString());
            var alpha = 1 - beta - gamma;
            var hit = ray.At(t);
            var rebuilt = new Point3D(
                alpha * v0.x + beta * v1.x + gamma * v2.x, alpha * v0.y + beta * v1.y + gamma * v2.y, alpha * v0.z + beta * v1.z + gamma * v2.z);
            Assert.True(hit.Distance(rebuilt) < 1e-12, $"{test}: {hit} against {rebuilt}");
        }
    }

    [Theory]
    [InlineData(TriangleTest.MollerTrumbore)]
    [InlineData(TriangleTest.Algebraic)]
    [InlineData(TriangleTest.Plucker)]
    [InlineData(TriangleTest.PluckerEdges)]
    public void Bih_with_each_test_equals_that_test_by_brute_force(TriangleTest test)
    {
        var mesh = RandomSoup(300, 21);
        mesh.TriangleTest = test;
        var triangles = mesh.CreateTriangles(smooth: false);
        var bih = new BoundingIntervalHierarchy(triangles);
        var hits = 0;
        foreach (var ray in RandomRays(300, 23, 8))
        {
            var expected = double.PositiveInfinity;
            foreach (var triangle in triangles)
                if (triangle.Intersect(ray, out var t) && t < expected)
                    expected = t;
            var hit = bih.IntersectNearest(ray, double.PositiveInfinity, out var found, out _);
            Assert.Equal(expected < double.PositiveInfinity, hit);
            if (hit)
            {
                Assert.Equal(expected, found); // same arithmetic in the packed leaves, so bit for bit
                hits++;
            }
        }

        Assert.True(hits > 30);
    }

    [Fact]
    public void Rays_parallel_to_the_plane_or_behind_the_origin_miss_for_every_test()
    {
        var mesh = new Mesh([new Point3D(0, 0, 0), new Point3D(1, 0, 0), new Point3D(0, 1, 0)], [0, 1, 2]);
        Ray[] misses = [new(new Point3D(0.2, 0.2, 1), new Vector3D(1, 0, 0)), new(new Point3D(0.2, 0.2, 1), new Vector3D(0, 0, 1)), new(new Point3D(2, 2, 1), new Vector3D(0, 0, -1))];
        foreach (var test in Enum.GetValues<TriangleTest>())
        {
            mesh.TriangleTest = test;
            var triangle = mesh.CreateTriangles(smooth: false)[0];
            foreach (var ray in misses)
                Assert.False(triangle.Intersect(ray, out _), $"{test} hit on {ray}");
        }
    }
}
