using RayTracer.Acceleration;
using RayTracer.Geometry;
using RayTracer.Geometry.Meshes;
using RayTracer.Geometry.Universal;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Acceleration;

public class AccelerationStructures_AgreeWithBruteForce
{
    public static TheoryData<string> Kinds => ["grid", "bih", "bvh", "bvh4"];

    private static AccelerationStructure Build(string kind, IReadOnlyList<GeometricObject> objects) => kind switch
    {
        "grid" => new RegularGrid(objects),
        "bih" => new BoundingIntervalHierarchy(objects),
        "bvh4" => new Bvh(objects, 4, BvhBuilder.Parallelism.Default, width: 4), // the fallback where the default is eight-wide
        _ => new Bvh(objects),
    };

    /// <summary>Random triangles of varied size (stand-alone and from a mesh) plus random spheres.</summary>
    private static List<GeometricObject> RandomScene(ulong seed, int triangles, int spheres, bool withPlane = false)
    {
        var random = new SeededRandom(seed);
        var objects = new List<GeometricObject>();
        Point3D RandomPoint(double r) => new(random.NextDouble(-r, r), random.NextDouble(-r, r), random.NextDouble(-r, r));

        var vertices = new Point3D[3 * triangles];
        for (int i = 0; i < triangles; i++)
        {
            var c = RandomPoint(10);
            double size = random.NextDouble() < 0.1 ? 4 : 0.6;
            for (int k = 0; k < 3; k++)
            {
                vertices[3 * i + k] = c + (RandomPoint(size) - Point3D.Origin);
            }
        }

        var mesh = new Mesh(vertices, [.. Enumerable.Range(0, vertices.Length)]);
        var meshTriangles = mesh.CreateTriangles(smooth: false);
        for (int i = 0; i < triangles; i++)
        {
            // Half as mesh triangles, half as stand-alone triangles: both take the packed fast path.
            objects.Add(i % 2 == 0 ? meshTriangles[i] : new Triangle(vertices[3 * i], vertices[3 * i + 1], vertices[3 * i + 2]));
        }

        for (int i = 0; i < spheres; i++)
        {
            objects.Add(new Sphere(RandomPoint(10), random.NextDouble(0.1, 1.5)));
        }

        if (withPlane)
        {
            objects.Add(new Plane(new Point3D(0, -12, 0), new Normal3D(0, 1, 0)));
        }

        return objects;
    }

    private static (double T, int Index) BruteForce(IReadOnlyList<GeometricObject> objects, in Ray ray)
    {
        double best = double.PositiveInfinity;
        int index = -1;
        for (int i = 0; i < objects.Count; i++)
        {
            if (objects[i].Intersect(ray, out double t) && t < best)
            {
                best = t;
                index = i;
            }
        }

        return (best, index);
    }

    private static Ray RandomRay(SeededRandom random, bool fromInside)
    {
        double r = fromInside ? 9 : 30;
        var origin = new Point3D(random.NextDouble(-r, r), random.NextDouble(-r, r), random.NextDouble(-r, r));
        var target = new Point3D(random.NextDouble(-10, 10), random.NextDouble(-10, 10), random.NextDouble(-10, 10));
        return new Ray(origin, target - origin);
    }

    [Theory]
    [MemberData(nameof(Kinds))]
    public void Nearest_hit_matches_brute_force(string kind)
    {
        var objects = RandomScene(100, 1500, 60, withPlane: true);
        var structure = Build(kind, objects);
        var random = new SeededRandom(200);
        int hits = 0;
        for (int n = 0; n < 4000; n++)
        {
            var ray = RandomRay(random, fromInside: n % 2 == 0);
            var (tExpected, expected) = BruteForce(objects, ray);
            bool hit = structure.IntersectNearest(ray, double.PositiveInfinity, out double t, out int primitive);
            Assert.Equal(expected >= 0, hit);
            if (!hit)
            {
                continue;
            }

            hits++;
            Assert.Equal(tExpected, t);
            // Identical t means the same surface unless two objects are hit at exactly the same point.
            var found = structure.GetPrimitive(primitive);
            Assert.True(ReferenceEquals(found, objects[expected]) || (found.Intersect(ray, out double tf) && tf == tExpected));
        }

        Assert.True(hits > 1000, $"only {hits} hits");
    }

    [Theory]
    [MemberData(nameof(Kinds))]
    public void Axis_aligned_rays_match_brute_force(string kind)
    {
        // Zero direction components exercise the infinite reciprocals in every traversal.
        var objects = RandomScene(101, 800, 40);
        var structure = Build(kind, objects);
        var random = new SeededRandom(201);
        for (int n = 0; n < 1500; n++)
        {
            var origin = new Point3D(random.NextDouble(-12, 12), random.NextDouble(-12, 12), random.NextDouble(-12, 12));
            int axis = n % 3;
            double sign = random.NextDouble() < 0.5 ? -1 : 1;
            var d = new Vector3D(axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0);
            var ray = new Ray(origin, d);
            var (tExpected, expected) = BruteForce(objects, ray);
            bool hit = structure.IntersectNearest(ray, double.PositiveInfinity, out double t, out _);
            Assert.Equal(expected >= 0, hit);
            if (hit)
            {
                Assert.Equal(tExpected, t);
            }
        }
    }

    [Theory]
    [MemberData(nameof(Kinds))]
    public void Any_hit_agrees_with_brute_force_within_the_distance(string kind)
    {
        var objects = RandomScene(102, 1000, 40, withPlane: true);
        var structure = Build(kind, objects);
        var random = new SeededRandom(202);
        for (int n = 0; n < 3000; n++)
        {
            var ray = RandomRay(random, fromInside: true);
            double maxDistance = random.NextDouble(0.05, 1.5);
            var (tExpected, _) = BruteForce(objects, ray);
            Assert.Equal(tExpected < maxDistance, structure.IntersectAny(ray, maxDistance));
            Assert.Equal(tExpected < maxDistance, structure.Occludes(ray, maxDistance));
        }
    }

    [Theory]
    [MemberData(nameof(Kinds))]
    public void Hit_fills_the_shading_record_of_the_nearest_primitive(string kind)
    {
        var objects = RandomScene(103, 300, 30);
        var structure = Build(kind, objects);
        var random = new SeededRandom(203);
        var viaStructure = new ShadingRecord();
        var direct = new ShadingRecord();
        for (int n = 0; n < 1000; n++)
        {
            var ray = RandomRay(random, fromInside: false);
            var (tExpected, expected) = BruteForce(objects, ray);
            bool hit = structure.Hit(ray, out double t, viaStructure);
            Assert.Equal(expected >= 0, hit);
            if (hit)
            {
                Assert.True(objects[expected].Hit(ray, out _, direct));
                Assert.Equal(tExpected, t);
                Assert.Equal(direct.Normal, viaStructure.Normal);
            }
        }
    }

    [Theory]
    [MemberData(nameof(Kinds))]
    public void Shadow_rays_ignore_meshes_that_cast_no_shadows(string kind)
    {
        var mesh = ThroughputReport.DisplacedSphere(500);
        mesh.CastsShadows = false;
        var objects = new List<GeometricObject>(mesh.CreateTriangles(false)) { new Sphere(new Point3D(0, 0, -5), 1) };
        var structure = Build(kind, objects);
        var ray = new Ray(new Point3D(0, 0, 5), new Vector3D(0, 0, -1));
        Assert.True(structure.IntersectNearest(ray, double.PositiveInfinity, out double t, out _) && t < 5);
        Assert.False(structure.IntersectAny(ray, 8)); // only the mesh lies within 8
        Assert.True(structure.IntersectAny(ray, 20)); // the sphere behind it does cast shadows
        Assert.True(structure.ShadowHit(ray, out t));
        Assert.Equal(9, t, 9);
    }

    [Theory]
    [MemberData(nameof(Kinds))]
    public void Empty_and_degenerate_scenes_are_handled(string kind)
    {
        var ray = new Ray(new Point3D(0, 0, 5), new Vector3D(0, 0, -1));
        Assert.False(Build(kind, []).IntersectNearest(ray, double.PositiveInfinity, out _, out _));

        // All triangles in one plane (a flat bounding box) and many identical ones.
        var flat = new List<GeometricObject>();
        for (int i = 0; i < 50; i++)
        {
            flat.Add(new Triangle(new Point3D(-1, -1, 0), new Point3D(1, -1, 0), new Point3D(0, 1, 0)));
            flat.Add(new Triangle(new Point3D(i, 0, 0), new Point3D(i + 1, 0, 0), new Point3D(i, 1, 0)));
        }

        var structure = Build(kind, flat);
        Assert.True(structure.IntersectNearest(ray, double.PositiveInfinity, out double t, out _));
        Assert.Equal(5, t, 12);
        Assert.True(structure.IntersectNearest(new Ray(new Point3D(30.2, 0.3, -4), new Vector3D(0, 0, 1)), double.PositiveInfinity, out t, out _));
        Assert.Equal(4, t, 12);
    }
}
