using RayTracer.Geometry;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Geometry.Instancing;

/// <summary>Asserts that two objects report the same hits (t, hit point, normal) on the same rays.</summary>
internal static class HitComparison
{
    public const double Tolerance = 1e-9;

    /// <summary>Returns how many of the rays hit.</summary>
    public static int AssertSameHits(GeometricObject expected, GeometricObject actual, IEnumerable<Ray> rays)
    {
        var a = new ShadingRecord();
        var b = new ShadingRecord();
        var hits = 0;
        foreach (var ray in rays)
        {
            var he = expected.Hit(ray, out var te, a);
            var ha = actual.Hit(ray, out var ta, b);
            Assert.True(he == ha, $"hit {he} vs {ha} on {ray}");
            Assert.Equal(he, actual.Intersect(ray, out var tIntersect));
            if (!he)
                continue;
            hits++;
            Assert.True(Math.Abs(te - ta) <= Tolerance * Math.Max(1, te), $"t {te} vs {ta} on {ray}");
            Assert.Equal(ta, tIntersect);
            var pe = ray.At(te);
            var pa = ray.At(ta);
            Assert.True((pe - pa).Length <= Tolerance * Math.Max(1, ((Vector3D)pe).Length), $"point {pe} vs {pa} on {ray}");
            Assert.True((a.Normal - b.Normal).Length <= Tolerance, $"normal {a.Normal} vs {b.Normal} on {ray}");
        }

        return hits;
    }

    /// <summary>Rays from a box of half-side <paramref name="spread"/> about <paramref name="centre"/> towards points near it.</summary>
    public static IEnumerable<Ray> RaysAround(SeededRandom random, Point3D centre, double spread, double aim, int count)
    {
        for (var i = 0; i < count; i++)
        {
            var origin = centre + RandomVector(random, spread);
            var target = centre + RandomVector(random, aim);
            yield return new Ray(origin, (target - origin) * random.NextDouble(0.5, 2));
        }
    }

    public static Vector3D RandomVector(SeededRandom random, double halfSide) => new(
        random.NextDouble(-halfSide, halfSide), random.NextDouble(-halfSide, halfSide), random.NextDouble(-halfSide, halfSide));

    public static Vector3D RandomUnit(SeededRandom random)
    {
        while (true)
        {
            var v = RandomVector(random, 1);
            var length = v.Length;
            if (length > 0.1 && length <= 1)
                return v / length;
        }
    }
}
