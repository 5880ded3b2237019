using RayTracer.Bounds;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Bounds;

public class BoundingBox_SlabTest
{
    private static readonly BoundingBox Box = new(new Point3D(-1, -2, -3), new Point3D(2, 1, 0.5));

    [Fact]
    public void Rays_aimed_at_interior_points_hit_and_bracket_them()
    {
        var random = new SeededRandom(21);
        for (int n = 0; n < 2000; n++)
        {
            var target = new Point3D(random.NextDouble(-1, 2), random.NextDouble(-2, 1), random.NextDouble(-3, 0.5));
            var origin = new Point3D(random.NextDouble(-20, 20), random.NextDouble(-20, 20), random.NextDouble(-20, 20));
            var ray = new Ray(origin, target - origin);
            Assert.True(Box.Hit(ray, out double t0, out double t1));
            Assert.True(t0 <= 1 + 1e-12 && 1 <= t1 + 1e-12, $"t = 1 not in [{t0}, {t1}]");
            if (!Box.Contains(origin))
            {
                // The entry point lies on the surface.
                var p = ray.At(t0);
                Assert.True(Box.Expanded(1e-9).Contains(p) && !Box.Expanded(-1e-9).StrictlyContains(p));
            }
        }
    }

    [Fact]
    public void Rays_pointing_away_miss()
    {
        var random = new SeededRandom(22);
        for (int n = 0; n < 1000; n++)
        {
            // From outside, moving away from the centre along every axis where the origin is outside.
            var origin = new Point3D(random.NextDouble(3, 9), random.NextDouble(-9, 9), random.NextDouble(-9, 9));
            var ray = new Ray(origin, new Vector3D(random.NextDouble(0.01, 1), random.NextDouble(-1, 1), random.NextDouble(-1, 1)));
            Assert.False(Box.Hit(ray, out _, out _));
        }
    }

    [Fact]
    public void Axis_parallel_rays_inside_and_outside_the_slab()
    {
        // Zero direction components produce infinite reciprocals; the result must follow the slab.
        Assert.True(Box.Hit(new Ray(new Point3D(0, 0, -10), new Vector3D(0, 0, 1)), out double t0, out double t1));
        Assert.Equal(7, t0, 12);
        Assert.Equal(10.5, t1, 9);
        Assert.False(Box.Hit(new Ray(new Point3D(5, 0, -10), new Vector3D(0, 0, 1)), out _, out _));
        // Lying exactly in a face plane counts as touching the box.
        Assert.True(Box.Hit(new Ray(new Point3D(-1, 0, -10), new Vector3D(0, 0, 1)), out _, out _));
    }

    [Fact]
    public void Box_behind_the_ray_is_missed()
    {
        Assert.False(Box.Hit(new Ray(new Point3D(0, 0, 5), new Vector3D(0, 0, 1)), out _, out _));
    }
}
