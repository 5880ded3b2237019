using Twister.Tessellation;

namespace Twister.Tests.Tessellation;

/// <summary>Independent measurements of a tessellation against the surface it came from.</summary>
internal static class MeshMeasure
{
    /// <summary>
    /// Largest distance between the surface at a random (u, v) inside a triangle and the flat triangle's
    /// point with the same barycentric coordinates, over <paramref name="samples"/> points per triangle.
    /// </summary>
    public static double MaxChordError(IParametricSurface surface, IEnumerable<Corner[]> triangles, int samples = 24, int seed = 7)
    {
        var random = new Random(seed);
        var worst = 0.0;
        foreach (var corners in triangles)
        {
            for (var k = 0; k < samples; k++)
            {
                double beta = random.NextDouble(), gamma = random.NextDouble();
                if (beta + gamma > 1)
                {
                    (beta, gamma) = (1 - beta, 1 - gamma);
                }

                var alpha = 1 - beta - gamma;
                Corner a = corners[0], b = corners[1], c = corners[2];
                var onSurface = surface.PointAt(
                    alpha * a.Parameter.U + beta * b.Parameter.U + gamma * c.Parameter.U,
                    alpha * a.Parameter.V + beta * b.Parameter.V + gamma * c.Parameter.V);
                var flat = new TwistablePoint(
                    alpha * a.Point.x + beta * b.Point.x + gamma * c.Point.x,
                    alpha * a.Point.y + beta * b.Point.y + gamma * c.Point.y,
                    alpha * a.Point.z + beta * b.Point.z + gamma * c.Point.z);
                worst = Math.Max(worst, Distance(onSurface, flat));
            }
        }

        return worst;
    }

    public static double MaxChordError(IParametricSurface surface, TriangleMesh mesh) => MaxChordError(surface, Triangles(mesh));

    public static IEnumerable<Corner[]> Triangles(TriangleMesh mesh)
    {
        for (var t = 0; t < mesh.TriangleCount; t++)
        {
            yield return [.. Enumerable.Range(0, 3).Select(k => mesh.Indices[3 * t + k]).Select(i => new Corner(mesh.Parameters[i], mesh.Positions[i]))];
        }
    }

    /// <summary>An n × n grid of cells, each cut into two triangles.</summary>
    public static List<Corner[]> UniformGrid(IParametricSurface surface, int n)
    {
        Corner At(int i, int j) => new(new SurfaceParameter((double)i / n, (double)j / n), surface.PointAt((double)i / n, (double)j / n));
        var triangles = new List<Corner[]>(2 * n * n);
        for (var i = 0; i < n; i++)
        {
            for (var j = 0; j < n; j++)
            {
                triangles.Add([At(i, j), At(i + 1, j), At(i + 1, j + 1)]);
                triangles.Add([At(i, j), At(i + 1, j + 1), At(i, j + 1)]);
            }
        }

        return triangles;
    }

    /// <summary>The smallest n whose n × n grid measures no more chord error than <paramref name="error"/>.</summary>
    public static int UniformCellsFor(IParametricSurface surface, double error)
    {
        int low = 3, high = 4;
        while (MaxChordError(surface, UniformGrid(surface, high)) > error)
        {
            low = high;
            high *= 2;
        }

        while (high - low > 1)
        {
            var mid = (low + high) / 2;
            if (MaxChordError(surface, UniformGrid(surface, mid)) > error)
            {
                low = mid;
            }
            else
            {
                high = mid;
            }
        }

        return high;
    }

    public readonly record struct Corner(SurfaceParameter Parameter, TwistablePoint Point);

    public static double Distance(TwistablePoint a, TwistablePoint b) =>
        Math.Sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));

    /// <summary>
    /// Asserts that the welded mesh is closed: every edge walked exactly once in each direction (two
    /// consistently wound triangles, no crack and no T-junction, since a vertex on one side of an
    /// edge only would leave an edge walked once), and that V − E + F is <paramref name="euler"/>.
    /// </summary>
    public static void AssertClosed(TriangleMesh mesh, int euler)
    {
        var directed = new Dictionary<(int, int), int>();
        for (var t = 0; t < mesh.TriangleCount; t++)
        {
            for (var k = 0; k < 3; k++)
            {
                int a = mesh.Welded[mesh.Indices[3 * t + k]], b = mesh.Welded[mesh.Indices[3 * t + (k + 1) % 3]];
                Assert.NotEqual(a, b);
                directed[(a, b)] = directed.GetValueOrDefault((a, b)) + 1;
            }
        }

        Assert.All(directed, e => Assert.Equal(1, e.Value));
        Assert.All(directed.Keys, e => Assert.True(directed.ContainsKey((e.Item2, e.Item1)), $"edge {e} has no twin"));
        var vertices = directed.Keys.Select(e => e.Item1).Distinct().Count();
        Assert.Equal(euler, vertices - directed.Count / 2 + mesh.TriangleCount);
    }
}
