using System.Runtime.Intrinsics;
using RayTracer.Geometry.Solvers;
using RayTracer.Kernels;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Kernels;

/// <summary>
/// The four-lane (<see cref="Vector256{T}"/>) and eight-lane (<see cref="Vector512{T}"/>, the eight-wide
/// BVH's) Möller–Trumbore tests: every lane gives bit for bit the distance of the scalar test on that
/// lane's triangle (the BVH's agreement with brute force rests on it), and hits land where plain
/// geometry says they do.
/// </summary>
public class TriangleGroupSolver_MatchesScalar
{
    private static Point3D RandomPoint(SeededRandom random, double r) =>
        new(random.NextDouble(-r, r), random.NextDouble(-r, r), random.NextDouble(-r, r));

    /// <summary>Per lane of a group of <paramref name="width"/> lanes (the first <paramref name="lanes"/> used), the distance along the ray.</summary>
    private static double[] Distances(int width, Point3D[] v0, Point3D[] v1, Point3D[] v2, int lanes, Ray ray, double tMax)
    {
        double[] Lane(Func<int, double> f) => [.. Enumerable.Range(0, width).Select(k => k < lanes ? f(k) : 0)];
        double[] X(Point3D[] p, Point3D[] from) => Lane(k => p[k].x - (from is null ? 0 : from[k].x));
        double[] Y(Point3D[] p, Point3D[] from) => Lane(k => p[k].y - (from is null ? 0 : from[k].y));
        double[] Z(Point3D[] p, Point3D[] from) => Lane(k => p[k].z - (from is null ? 0 : from[k].z));
        if (width == 4)
        {
            Vector3x4 Vec(Point3D[] p, Point3D[] from) =>
                new() { x = Vector256.Create(X(p, from)), y = Vector256.Create(Y(p, from)), z = Vector256.Create(Z(p, from)) };
            var group = new TriangleGroup4 { V0 = Vec(v0, null!), E1 = Vec(v1, v0), E2 = Vec(v2, v0) };
            var t = TriangleGroupSolver.Distances(new TriangleGroupSolver.RayLanes(ray), ref group, Vector256.Create(tMax));
            return [.. Enumerable.Range(0, 4).Select(k => t.GetElement(k))];
        }
        else
        {
            Vector3x8 Vec(Point3D[] p, Point3D[] from) =>
                new() { x = Vector512.Create(X(p, from)), y = Vector512.Create(Y(p, from)), z = Vector512.Create(Z(p, from)) };
            var group = new TriangleGroup8 { V0 = Vec(v0, null!), E1 = Vec(v1, v0), E2 = Vec(v2, v0) };
            var t = TriangleGroup8Solver.Distances(new TriangleGroup8Solver.RayLanes(ray), ref group, Vector512.Create(tMax));
            return [.. Enumerable.Range(0, 8).Select(k => t.GetElement(k))];
        }
    }

    [Theory]
    [InlineData(4)]
    [InlineData(8)]
    public void Every_lane_is_the_scalar_distance_bit_for_bit_on_vertices_edges_and_random_points(int width)
    {
        var random = new SeededRandom((ulong)(29 * width));
        int hits = 0;
        for (int n = 0; n < 3000; n++)
        {
            int lanes = 1 + n % width;
            var v0 = new Point3D[width];
            var v1 = new Point3D[width];
            var v2 = new Point3D[width];
            for (int k = 0; k < width; k++)
            {
                var c = RandomPoint(random, 3);
                v0[k] = c + (RandomPoint(random, 1) - Point3D.Origin);
                v1[k] = c + (RandomPoint(random, 1) - Point3D.Origin);
                v2[k] = c + (RandomPoint(random, 1) - Point3D.Origin);
            }

            // Aim at a vertex, an edge's midpoint, a point along an edge's line or anywhere near lane 0.
            var origin = RandomPoint(random, 8);
            var target = (n % 5) switch
            {
                0 => v1[0],
                1 => v0[0] + 0.5 * (v2[0] - v0[0]),
                2 => v0[0] + random.NextDouble(-0.5, 1.5) * (v1[0] - v0[0]),
                _ => RandomPoint(random, 4),
            };
            if (n % 7 == 6)
                origin = v0[0] + 2 * (v0[0] - v1[0]); // on lane 0's edge line, looking along it
            var ray = new Ray(origin, target - origin) { tMin = n % 3 == 0 ? 1e-9 : 0 };
            double tMax = n % 4 == 0 ? random.NextDouble(0.2, 3) : double.PositiveInfinity;

            var t = Distances(width, v0, v1, v2, lanes, ray, tMax);
            for (int k = 0; k < width; k++)
            {
                double expected = k < lanes
                    ? TriangleSolver.Distance(ray, v0[k], v1[k] - v0[k], v2[k] - v0[k], tMax)
                    : double.PositiveInfinity; // an empty lane never hits
                Assert.Equal(BitConverter.DoubleToInt64Bits(expected), BitConverter.DoubleToInt64Bits(t[k]));
                hits += double.IsFinite(expected) ? 1 : 0;
            }
        }

        Assert.True(hits > 500, $"only {hits} lane hits");
    }

    [Theory]
    [InlineData(4)]
    [InlineData(8)]
    public void A_ray_aimed_inside_a_lane_hits_it_at_the_aimed_distance(int width)
    {
        // Independent truth: the ray o + t (p − o) reaches p, a point inside the triangle, at t = 1.
        var random = new SeededRandom((ulong)(30 * width));
        for (int n = 0; n < 500; n++)
        {
            var v0 = new Point3D[width];
            var v1 = new Point3D[width];
            var v2 = new Point3D[width];
            for (int k = 0; k < width; k++)
            {
                v0[k] = RandomPoint(random, 3);
                v1[k] = RandomPoint(random, 3);
                v2[k] = RandomPoint(random, 3);
            }

            int lane = n % width;
            double b = random.NextDouble(0.1, 0.4), g = random.NextDouble(0.1, 0.4);
            var p = v0[lane] + b * (v1[lane] - v0[lane]) + g * (v2[lane] - v0[lane]);
            var o = RandomPoint(random, 10);
            var t = Distances(width, v0, v1, v2, width, new Ray(o, p - o), double.PositiveInfinity);
            Assert.Equal(1, t[lane], 1e-9);

            // Outside the triangle (beyond the edge v1–v2) the lane misses.
            var q = v0[lane] + 0.7 * (v1[lane] - v0[lane]) + 0.6 * (v2[lane] - v0[lane]);
            t = Distances(width, v0, v1, v2, width, new Ray(o, q - o), double.PositiveInfinity);
            Assert.NotEqual(1, t[lane], 1e-6);
        }
    }
}
