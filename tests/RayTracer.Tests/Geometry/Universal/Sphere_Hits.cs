using RayTracer.Geometry.Universal;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Geometry.Universal;

public class Sphere_Hits
{
    private static readonly Sphere Unit = new(new Point3D(1, 2, 3), 2);

    [Fact]
    public void Head_on_ray_hits_at_distance_minus_radius()
    {
        var sr = new ShadingRecord();
        Assert.True(Unit.Hit(new Ray(new Point3D(1, 2, 13), new Vector3D(0, 0, -1)), out double t, sr));
        Assert.Equal(8, t, 12);
        Assert.Equal(new Normal3D(0, 0, 1), sr.Normal);
    }

    [Fact]
    public void Ray_from_inside_hits_the_far_side_with_outward_normal()
    {
        var sr = new ShadingRecord();
        Assert.True(Unit.Hit(new Ray(new Point3D(1, 2, 3), new Vector3D(0, 2, 0)), out double t, sr));
        Assert.Equal(1, t, 12); // direction length 2, radius 2
        Assert.Equal(1, sr.Normal.y, 12);
    }

    [Fact]
    public void Grazing_rays_hit_just_inside_and_miss_just_outside()
    {
        var origin = new Point3D(1, 2 + 2 - 1e-6, -10);
        Assert.True(Unit.Intersect(new Ray(origin, new Vector3D(0, 0, 1)), out double t));
        Assert.Equal(13, t, 2);
        Assert.False(Unit.Intersect(new Ray(new Point3D(1, 2 + 2 + 1e-6, -10), new Vector3D(0, 0, 1)), out _));
    }

    [Fact]
    public void Sphere_behind_the_ray_is_missed()
    {
        Assert.False(Unit.Intersect(new Ray(new Point3D(1, 2, 10), new Vector3D(0, 0, 1)), out _));
    }

    [Fact]
    public void Random_hits_lie_on_the_surface_with_unit_outward_normals()
    {
        var random = new SeededRandom(51);
        var sr = new ShadingRecord();
        int hits = 0;
        for (int n = 0; n < 2000; n++)
        {
            var ray = ImplicitSurfaceMarch.RandomRayTowards(random, 8, 3);
            ray.o = ray.o + new Vector3D(1, 2, 3);
            if (!Unit.Hit(ray, out double t, sr))
            {
                continue;
            }

            hits++;
            var p = ray.At(t);
            Assert.Equal(2, p.Distance(Unit.Center), 9);
            Assert.Equal(1, sr.Normal.Length, 12);
            Assert.True(sr.Normal.Dot(p - Unit.Center) > 0);
            Assert.InRange(sr.TextureCoordinates.u, 0, 1);
            Assert.InRange(sr.TextureCoordinates.v, 0, 1);
        }

        Assert.True(hits > 500);
    }

    [Fact]
    public void Samples_lie_on_the_surface_and_pdf_is_one_over_area()
    {
        var random = new SeededRandom(52);
        var mean = Vector3D.Zero;
        for (int n = 0; n < 20_000; n++)
        {
            var p = Unit.Sample(new Point2D(random.NextDouble(), random.NextDouble()));
            Assert.Equal(2, p.Distance(Unit.Center), 12);
            mean += (p - Unit.Center) / 20_000;
        }

        // Uniform samples average to the centre (standard error about 0.008 per axis).
        Assert.True(mean.Length < 0.06, $"mean offset {mean}");
        Assert.Equal(1 / (16 * Math.PI), Unit.Pdf(new ShadingRecord()), 15);
    }
}
