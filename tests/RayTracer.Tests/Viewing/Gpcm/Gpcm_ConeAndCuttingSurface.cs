using RayTracer.Maths;
using RayTracer.Viewing;

namespace RayTracer.Tests.Viewing.Gpcm;

public class Gpcm_ConeAndCuttingSurface
{
    private static ViewPlane Plane() => new() { HorizontalResolution = 60, VerticalResolution = 20, PixelSize = 1 };

    [Fact]
    public void Cone_points_lie_on_the_cone_about_image_up_at_the_azimuth_of_u()
    {
        const double maxAzimuth = 2.5, slant = 1.6, tilt = 0.4;
        var cone = GpcmSurfaces.Cone(maxAzimuth, slant, tilt);
        var random = new Random(5);
        for (var k = 0; k < 200; k++)
        {
            double u = random.NextDouble(), v = random.NextDouble();
            var p = cone.PointAt(u, v);
            var s = slant * (v - 0.5);
            var radius = 1 - s * Math.Sin(tilt);
            var azimuth = (2 * u - 1) * maxAzimuth;
            Assert.Equal(radius * Math.Sin(azimuth), p.x, 1e-12);
            Assert.Equal(s * Math.Cos(tilt), p.y, 1e-12);
            Assert.Equal(-radius * Math.Cos(azimuth), p.z, 1e-12);
        }
    }

    [Fact]
    public void Untilted_cone_is_the_cylinder()
    {
        var cone = GpcmSurfaces.Cone(1.2, 0.9, 0);
        var cylinder = GpcmSurfaces.Cylinder(1.2, 0.9);
        for (var u = 0.0; u <= 1; u += 0.125)
        for (var v = 0.0; v <= 1; v += 0.125)
        {
            var a = cone.PointAt(u, v);
            var b = cylinder.PointAt(u, v);
            Assert.True(Math.Abs(a.x - b.x) + Math.Abs(a.y - b.y) + Math.Abs(a.z - b.z) < 1e-14, $"({u}, {v}): {a} vs {b}");
        }
    }

    [Fact]
    public void Cone_that_would_pass_its_apex_or_lie_flat_is_refused_with_a_message()
    {
        var apex = Assert.Throws<ArgumentOutOfRangeException>(() => GpcmSurfaces.Cone(Math.PI, 6, 0.5));
        Assert.Contains("apex", apex.Message);
        Assert.Throws<ArgumentOutOfRangeException>(() => GpcmSurfaces.Cone(Math.PI, 1, Math.PI / 2));
    }

    [Fact]
    public void Conic_camera_for_a_tall_image_stops_short_of_the_apex()
    {
        // A square image for a full turn would ask for a slant of 2π, past the apex at the default tilt.
        var square = new ViewPlane { HorizontalResolution = 20, VerticalResolution = 20 };
        var cone = (ConeLens)RayTracer.Viewing.Gpcm.Conic(360, square).Surface;
        var top = cone.PointAt(0.5, 1);
        var bottom = cone.PointAt(0.5, 0);
        Assert.Equal(0.2, -top.z, 1e-12);
        Assert.Equal(1.8, -bottom.z, 1e-12);
    }

    [Fact]
    public void Conic_camera_sees_the_look_at_point_at_the_image_centre()
    {
        var camera = RayTracer.Viewing.Gpcm.Conic(300, Plane());
        camera.Eye = new Point3D(1, 2, 3);
        camera.LookAt = new Point3D(4, -1, 7);
        camera.Up = new Vector3D(0.3, 0, 1);
        camera.Orient();
        Assert.True(camera.GetRay(new Point2D(0, 0), Plane(), out var ray));
        var expected = (camera.LookAt - camera.Eye).Normalized();
        Assert.True((ray.d - expected).Length < 1e-12, $"{ray.d} vs {expected}");
    }

    [Theory]
    [InlineData(GpcmRayDirection.Outward)]
    [InlineData(GpcmRayDirection.Inward)]
    public void Surface_origin_starts_rays_on_the_scaled_oriented_surface(GpcmRayDirection direction)
    {
        var vp = Plane();
        var reference = RayTracer.Viewing.Gpcm.Cylindrical(270, vp);
        var cutting = RayTracer.Viewing.Gpcm.Cylindrical(270, vp);
        cutting.RayOrigin = GpcmRayOrigin.Surface;
        cutting.RayDirection = direction;
        cutting.SurfaceScale = 2.5;
        foreach (var camera in new[] { reference, cutting })
        {
            camera.Eye = new Point3D(-3, 1, 2);
            camera.LookAt = new Point3D(5, 0, -1);
            camera.Up = new Vector3D(0, 0, 1);
            camera.Orient();
        }

        var random = new Random(9);
        for (var k = 0; k < 100; k++)
        {
            var pp = new Point2D((random.NextDouble() - 0.5) * 60, (random.NextDouble() - 0.5) * 20);
            Assert.True(reference.GetRay(pp, vp, out var fromEye));
            Assert.True(cutting.GetRay(pp, vp, out var fromSurface));
            var u = pp.x / 60 + 0.5;
            var v = pp.y / 20 + 0.5;
            var s = cutting.Surface.PointAt(u, v);
            var surfacePoint = cutting.Eye + 2.5 * cutting.Orientation!.ToWorld(new Vector3D(s.x, s.y, s.z));
            Assert.True((fromSurface.o - surfacePoint).Length < 1e-12);
            // The surface point lies on the eye's ray, and the direction is that ray's or its reverse.
            var along = fromSurface.o - fromEye.o;
            Assert.True(along.Cross(fromEye.d).Length < 1e-12 && along.Dot(fromEye.d) > 0);
            var sign = direction == GpcmRayDirection.Outward ? 1 : -1;
            Assert.True((fromSurface.d - sign * fromEye.d).Length < 1e-15);
        }
    }

    [Fact]
    public void Surface_scale_must_be_positive_and_finite()
    {
        var camera = RayTracer.Viewing.Gpcm.Fisheye(180);
        Assert.Throws<ArgumentOutOfRangeException>(() => camera.SurfaceScale = 0);
        Assert.Throws<ArgumentOutOfRangeException>(() => camera.SurfaceScale = double.PositiveInfinity);
    }
}
