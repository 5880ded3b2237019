using System.Runtime.Intrinsics;
using RayTracer.Geometry.Solvers;
using RayTracer.Kernels;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Kernels;

/// <summary>
/// The eight-lane Möller–Trumbore test (<see cref="Vector512{T}"/>, used by the eight-wide BVH): every lane
/// gives bit for bit the distance of the scalar test on that lane's triangle (the BVH's agreement with brute
/// force rests on it), and hits land where plain geometry says they do.
/// </summary>
public class TriangleGroup8Solver_MatchesScalar
{
    private static Point3D RandomPoint(SeededRandom random, double r) =>
        new(random.NextDouble(-r, r), random.NextDouble(-r, r), random.NextDouble(-r, r));

    private static TriangleGroup8 Group(Point3D[] v0, Point3D[] v1, Point3D[] v2, int lanes)
    {
        double[] Lane(Func<int, double> f) => [.. Enumerable.Range(0, 8).Select(k => k < lanes ? f(k) : 0)];
        Vector3x8 Vec(Func<int, double> x, Func<int, double> y, Func<int, double> z) =>
            new() { x = Vector512.Create(Lane(x)), y = Vector512.Create(Lane(y)), z = Vector512.Create(Lane(z)) };
        return new TriangleGroup8
        {
            V0 = Vec(k => v0[k].x, k => v0[k].y, k => v0[k].z),
            E1 = Vec(k => v1[k].x - v0[k].x, k => v1[k].y - v0[k].y, k => v1[k].z - v0[k].z),
            E2 = Vec(k => v2[k].x - v0[k].x, k => v2[k].y - v0[k].y, k => v2[k].z - v0[k].z),
        };
    }

    [Fact]
    public void Every_lane_is_the_scalar_distance_bit_for_bit_on_vertices_edges_and_random_points()
    {
        var random = new SeededRandom(2908);
        int hits = 0;
        for (int n = 0; n < 3000; n++)
        {
            int lanes = 1 + n % 8;
            var v0 = new Point3D[8];
            var v1 = new Point3D[8];
            var v2 = new Point3D[8];
            for (int k = 0; k < 8; k++)
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

            var group = Group(v0, v1, v2, lanes);
            var t = TriangleGroup8Solver.Distances(new TriangleGroup8Solver.RayLanes(ray), ref group, Vector512.Create(tMax));
            for (int k = 0; k < 8; k++)
            {
                double expected = k < lanes
                    ? TriangleSolver.Distance(ray, v0[k], v1[k] - v0[k], v2[k] - v0[k], tMax)
                    : double.PositiveInfinity; // an empty lane never hits
                Assert.Equal(BitConverter.DoubleToInt64Bits(expected), BitConverter.DoubleToInt64Bits(t.GetElement(k)));
                hits += double.IsFinite(expected) ? 1 : 0;
            }
        }

        Assert.True(hits > 500, $"only {hits} lane hits");
    }

    [Fact]
    public void A_ray_aimed_inside_a_lane_hits_it_at_the_aimed_distance()
    {
        // Independent truth: the ray o + t (p − o) reaches p, a point inside the triangle, at t = 1.
        var random = new SeededRandom(2909);
        for (int n = 0; n < 500; n++)
        {
            var v0 = new Point3D[8];
            var v1 = new Point3D[8];
            var v2 = new Point3D[8];
            for (int k = 0; k < 8; k++)
            {
                v0[k] = RandomPoint(random, 3);
                v1[k] = RandomPoint(random, 3);
                v2[k] = RandomPoint(random, 3);
            }

            int lane = n % 8;
            double b = random.NextDouble(0.1, 0.4), g = random.NextDouble(0.1, 0.4);
            var p = v0[lane] + b * (v1[lane] - v0[lane]) + g * (v2[lane] - v0[lane]);
            var o = RandomPoint(random, 10);
            var group = Group(v0, v1, v2, 8);
            var t = TriangleGroup8Solver.Distances(new TriangleGroup8Solver.RayLanes(new Ray(o, p - o)), ref group, Vector512.Create(double.PositiveInfinity));
            Assert.Equal(1, t.GetElement(lane), 1e-9);

            // Outside the triangle (beyond the edge v1–v2) the lane misses.
            var q = v0[lane] + 0.7 * (v1[lane] - v0[lane]) + 0.6 * (v2[lane] - v0[lane]);
            t = TriangleGroup8Solver.Distances(new TriangleGroup8Solver.RayLanes(new Ray(o, q - o)), ref group, Vector512.Create(double.PositiveInfinity));
            Assert.NotEqual(1, t.GetElement(lane), 1e-6);
        }
    }
}
