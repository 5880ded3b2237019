using RayTracer.Bounds;
using RayTracer.Geometry;
using RayTracer.Geometry.Universal;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Geometry;

public class Instance_Hits
{
    [Fact]
    public void Instanced_unit_sphere_matches_the_analytic_sphere()
    {
        // Uniform scale 2, rotation and translation: the image is the sphere of radius 2 at the moved centre.
        var instance = new Instance(new Sphere(Point3D.Origin, 1))
            .Scale(2).RotateY(0.7).RotateX(-0.3).Translate(3, -1, 2);
        var reference = new Sphere(new Point3D(3, -1, 2), 2);
        var random = new SeededRandom(81);
        var a = new ShadingRecord();
        var b = new ShadingRecord();
        int hits = 0;
        for (int n = 0; n < 2000; n++)
        {
            var ray = ImplicitSurfaceMarch.RandomRayTowards(random, 10, 3);
            ray.o += new Vector3D(3, -1, 2);
            bool hi = instance.Hit(ray, out double ti, a);
            bool hr = reference.Hit(ray, out double tr, b);
            Assert.Equal(hr, hi);
            if (hi)
            {
                hits++;
                Assert.Equal(tr, ti, 9);
                Assert.True((a.Normal - b.Normal).Length < 1e-9, $"{a.Normal} vs {b.Normal}");
            }
        }

        Assert.True(hits > 300);
    }

    [Fact]
    public void Non_uniform_scale_gives_the_ellipsoid_normal()
    {
        // x²/4 + y² + z² = 1; normal ∝ (x/4, y, z).
        var ellipsoid = new Instance(new Sphere(Point3D.Origin, 1)).Scale(2, 1, 1);
        var sr = new ShadingRecord();
        var origin = new Point3D(5, 5, 0);
        var target = new Point3D(2 * Math.Cos(0.6), Math.Sin(0.6), 0);
        Assert.True(ellipsoid.Hit(new Ray(origin, target - origin), out double t, sr));
        Assert.Equal(1, t, 9);
        var expected = new Normal3D(target.x / 4, target.y, 0).Normalized();
        Assert.True((sr.Normal - expected).Length < 1e-9);
        Assert.Equal(new BoundingBox(new Point3D(-2, -1, -1), new Point3D(2, 1, 1)).Max, ellipsoid.GetBoundingBox().Max);
    }
}
