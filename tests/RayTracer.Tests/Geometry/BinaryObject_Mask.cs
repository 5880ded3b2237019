using RayTracer.Geometry;
using RayTracer.Geometry.Universal;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Tests.Geometry;

public class BinaryObject_Mask
{
    [Fact]
    public void Binary_object_shows_the_base_surface_only_where_the_mask_is_set()
    {
        // Keep the half of the sphere with u < 0.5 (azimuth from +z towards +x below π, i.e. x > 0).
        var masked = new BinaryObject(new Sphere(Point3D.Origin, 1), sr => sr.TextureCoordinates.u < 0.5);
        var sr = new ShadingRecord();
        // Coming from +x the front (x > 0) is kept.
        Assert.True(masked.Hit(new Ray(new Point3D(5, 0.1, 0.2), new Vector3D(-1, 0, 0)), out double t, sr));
        Assert.True(Math.Abs(t - (5 - Math.Sqrt(1 - 0.05))) < 1e-9);
        // Coming from -x the front is cut away; the ray goes on to the kept back half.
        Assert.True(masked.Hit(new Ray(new Point3D(-5, 0.1, 0.2), new Vector3D(1, 0, 0)), out t, sr));
        Assert.True(Math.Abs(t - (5 + Math.Sqrt(1 - 0.05))) < 1e-9);
        Assert.True(new Ray(new Point3D(-5, 0.1, 0.2), new Vector3D(1, 0, 0)).At(t).x > 0);
    }

    [Fact]
    public void A_fully_masked_ray_misses_and_leaves_the_record_untouched()
    {
        // Keep only the cap y > 0.9: a ray along the x axis crosses the sphere twice, both masked out.
        var masked = new BinaryObject(new Sphere(Point3D.Origin, 1), sr => sr.LocalHitPoint.y > 0.9);
        var sr = new ShadingRecord() { Normal = new Normal3D(7, 7, 7) };
        Assert.False(masked.Hit(new Ray(new Point3D(-5, 0, 0), new Vector3D(1, 0, 0)), out _, sr));
        Assert.Equal(new Normal3D(7, 7, 7), sr.Normal);
        Assert.False(masked.Intersect(new Ray(new Point3D(-5, 0, 0), new Vector3D(1, 0, 0)), out _));
        Assert.True(masked.Hit(new Ray(new Point3D(0, 5, 0), new Vector3D(0, -1, 0)), out double t, sr));
        Assert.Equal(4, t, 12);
        Assert.Equal(new Normal3D(0, 1, 0), sr.Normal);
    }
}
