using RayTracer.Geometry.Universal;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Geometry.Universal;

public class FlatPrimitives_Hits
{
    [Fact]
    public void Plane_hit_is_at_the_analytic_distance()
    {
        var plane = new Plane(new Point3D(0, 1, 0), new Normal3D(0, 2, 0));
        var sr = new ShadingRecord();
        Assert.True(plane.Hit(new Ray(new Point3D(3, 5, 1), new Vector3D(1, -2, 0)), out double t, sr));
        Assert.Equal(2, t, 12);
        Assert.Equal(new Normal3D(0, 1, 0), sr.Normal);
        // Parallel rays, even inside the plane, and rays pointing away miss.
        Assert.False(plane.Intersect(new Ray(new Point3D(0, 1, 0), new Vector3D(1, 0, 0)), out _));
        Assert.False(plane.Intersect(new Ray(new Point3D(0, 3, 0), new Vector3D(0, 1, 0)), out _));
    }

    [Fact]
    public void Disk_accepts_points_inside_the_radius_only()
    {
        var disk = new Disk(new Point3D(1, 1, 1), new Normal3D(1, 1, 1), 2);
        var n = new Vector3D(1, 1, 1).Normalized();
        var frame = OrthonormalBasis.FromW(n);
        var inside = new Point3D(1, 1, 1) + 1.999 * frame.U;
        var outside = new Point3D(1, 1, 1) + 2.001 * frame.V;
        Assert.True(disk.Intersect(new Ray(inside + 3 * n, -n), out double t));
        Assert.Equal(3, t, 12);
        Assert.False(disk.Intersect(new Ray(outside + 3 * n, -n), out _));
        var sample = disk.Sample(new Point2D(0.999, 0.3));
        Assert.Equal(0, Vector3D.Dot(sample - disk.Center, n), 12);
        Assert.True(sample.Distance(disk.Center) <= 2);
    }

    [Fact]
    public void Rectangle_reports_parametric_coordinates()
    {
        var rect = new Rectangle(new Point3D(0, 0, 0), new Vector3D(4, 0, 0), new Vector3D(0, 0, 2));
        var sr = new ShadingRecord();
        Assert.True(rect.Hit(new Ray(new Point3D(1, -5, 1.5), new Vector3D(0, 1, 0)), out double t, sr));
        Assert.Equal(5, t, 12);
        Assert.Equal(0.25, sr.TextureCoordinates.u, 12);
        Assert.Equal(0.75, sr.TextureCoordinates.v, 12);
        // a × b = (4,0,0) × (0,0,2) = (0,-8,0)
        Assert.Equal(new Normal3D(0, -1, 0), sr.Normal);
        Assert.False(rect.Intersect(new Ray(new Point3D(4.01, -5, 1), new Vector3D(0, 1, 0)), out _));
        Assert.Equal(1.0 / 8, rect.Pdf(sr), 15);
    }

    [Fact]
    public void Triangle_hits_match_barycentric_construction()
    {
        var random = new SeededRandom(61);
        var sr = new ShadingRecord();
        for (int n = 0; n < 1000; n++)
        {
            Point3D a = RandomPoint(random), b = RandomPoint(random), c = RandomPoint(random);
            var tri = new Triangle(a, b, c);
            double beta = random.NextDouble(), gamma = random.NextDouble() * (1 - beta);
            var target = a + beta * (b - a) + gamma * (c - a);
            var origin = RandomPoint(random) + new Vector3D(0, 0, 20);
            var ray = new Ray(origin, target - origin);
            if (tri.Area < 1e-3)
            {
                continue;
            }

            Assert.True(tri.Hit(ray, out double t, sr));
            Assert.Equal(1, t, 7);
            Assert.Equal(beta, sr.TextureCoordinates.u, 6);
            Assert.Equal(gamma, sr.TextureCoordinates.v, 6);
            Assert.Equal(0, sr.Normal.Dot(b - a), 9);
            Assert.Equal(0, sr.Normal.Dot(c - a), 9);

            // Just outside edge bc (beta + gamma slightly above 1) misses.
            var beyond = a + 0.5005 * (b - a) + 0.5005 * (c - a);
            Assert.False(tri.Intersect(new Ray(origin, beyond - origin), out _));
        }
    }

    [Fact]
    public void Box_faces_and_inside_origins()
    {
        var box = new Box(new Point3D(-1, -1, -1), new Point3D(1, 2, 3));
        var sr = new ShadingRecord();
        Assert.True(box.Hit(new Ray(new Point3D(0, 0, 10), new Vector3D(0, 0, -1)), out double t, sr));
        Assert.Equal(7, t, 12);
        Assert.Equal(new Normal3D(0, 0, 1), sr.Normal);
        Assert.True(box.Hit(new Ray(new Point3D(0, 0, 0), new Vector3D(-1, 0, 0)), out t, sr));
        Assert.Equal(1, t, 12);
        Assert.Equal(new Normal3D(-1, 0, 0), sr.Normal); // outward, though seen from inside
        Assert.False(box.Intersect(new Ray(new Point3D(0, 2.0001, 10), new Vector3D(0, 0, -1)), out _));
        Assert.True(box.Intersect(new Ray(new Point3D(0, 1.9999, 10), new Vector3D(0, 0, -1)), out _));
    }

    [Fact]
    public void Box_agrees_with_brute_force_marching()
    {
        var box = new Box(new Point3D(-1, -0.5, -2), new Point3D(1.5, 1, 1));
        static double F(Point3D p) => Math.Max(Math.Max(Math.Abs(p.x - 0.25) - 1.25, Math.Abs(p.y - 0.25) - 0.75), Math.Abs(p.z + 0.5) - 1.5);
        var random = new SeededRandom(62);
        for (int n = 0; n < 300; n++)
        {
            var ray = ImplicitSurfaceMarch.RandomRayTowards(random, 6, 2.5);
            if (box.GetBoundingBox().Hit(ray, out double t0, out double t1) && t1 - Math.Max(t0, 0) < 0.01)
            {
                continue; // a corner clipped by less than the marching step cannot be seen by marching
            }

            double? expected = ImplicitSurfaceMarch.FirstRoot(F, ray, 20, 2e-3);
            bool hit = box.Intersect(ray, out double t);
            Assert.Equal(expected.HasValue, hit);
            if (hit)
            {
                Assert.Equal(expected!.Value, t, 6);
            }
        }
    }

    private static Point3D RandomPoint(SeededRandom random) =>
        new(random.NextDouble(-3, 3), random.NextDouble(-3, 3), random.NextDouble(-3, 3));
}
