using RayTracer.Maths;
using RayTracer.Viewing;

namespace RayTracer.Tests.Viewing.Gpcm;

public class Gpcm_Catalogue
{
    private static ViewPlane Plane() => new() { HorizontalResolution = 40, VerticalResolution = 30, PixelSize = 0.5 };

    private static Vector3D RandomVector(Random random, double scale) =>
        new(scale * (2 * random.NextDouble() - 1), scale * (2 * random.NextDouble() - 1), scale * (2 * random.NextDouble() - 1));

    private static Point3D RandomPoint(Random random) => Point3D.Origin + RandomVector(random, 50);

    // Anywhere on the 20 × 15 view plane, edges included.
    private static Point2D RandomViewPoint(Random random) => new((random.NextDouble() - 0.5) * 20, (random.NextDouble() - 0.5) * 15);

    private static void AssertClose(Vector3D expected, Vector3D actual, double tolerance = 1e-12)
    {
        Assert.True((expected - actual).Length <= tolerance, $"expected {expected}, got {actual}");
    }

    public static TheoryData<Vector3D> Ups => new()
    {
        new Vector3D(0, 1, 0),
        new Vector3D(0, -1, 0),
        new Vector3D(0, 0, 3),
        new Vector3D(1, 2, -0.5),
    };

    private static void Place(Camera camera, Point3D eye, Point3D lookAt, Vector3D up)
    {
        camera.Eye = eye;
        camera.LookAt = lookAt;
        camera.Up = up;
    }

    [Theory]
    [MemberData(nameof(Ups))]
    public void Spherical_gpcm_gives_the_spherical_panorama_cameras_primary_rays(Vector3D up)
    {
        var vp = Plane();
        var random = new Random(21);
        var fields = new[] { (360.0, 180.0), (180.0, 90.0), (90.0, 45.0), (250.0, 170.0) };
        for (var trial = 0; trial < 20; trial++)
        {
            var eye = RandomPoint(random);
            var lookAt = RandomPoint(random);
            var (horizontal, vertical) = fields[trial % fields.Length];
            var panorama = new SphericalCamera { MaxLambdaDegrees = horizontal / 2, MaxPsiDegrees = vertical / 2 };
            Place(panorama, eye, lookAt, up);
            panorama.ComputeUVW();
            var gpcm = RayTracer.Viewing.Gpcm.Spherical(horizontal, vertical);
            Place(gpcm, eye, lookAt, up);
            gpcm.Orient();
            for (var k = 0; k < 50; k++)
            {
                var pp = RandomViewPoint(random);
                Assert.True(panorama.GetRay(pp, vp, out var expected));
                Assert.True(gpcm.GetRay(pp, vp, out var actual));
                AssertClose((Vector3D)expected.o, (Vector3D)actual.o);
                AssertClose(expected.d.Normalized(), actual.d);
                Assert.Equal(1, actual.d.Length, 12);
            }
        }
    }

    [Fact]
    public void Spherical_gpcm_with_one_angle_spans_half_as_much_elevation()
    {
        var vp = Plane();
        var camera = RayTracer.Viewing.Gpcm.Spherical(180);
        Place(camera, new Point3D(0, 0, 0), new Point3D(0, 0, -1), Vector3D.UnitY);
        camera.Orient();
        // The top edge of the image is 45° up, the right edge 90° to the right.
        Assert.True(camera.GetRay(new Point2D(0, 7.5), vp, out var top));
        AssertClose(new Vector3D(0, Math.Sqrt(0.5), -Math.Sqrt(0.5)), top.d);
        Assert.True(camera.GetRay(new Point2D(10, 0), vp, out var right));
        AssertClose(Vector3D.UnitX, right.d);
    }

    [Theory]
    [MemberData(nameof(Ups))]
    public void Polar_mapped_cap_gives_the_fisheye_cameras_primary_rays(Vector3D up)
    {
        var vp = Plane();
        var random = new Random(5);
        var fields = new[] { 180.0, 360.0, 90.0, 237.0 };
        var seen = 0;
        for (var trial = 0; trial < 20; trial++)
        {
            var eye = RandomPoint(random);
            var lookAt = RandomPoint(random);
            var degrees = fields[trial % fields.Length];
            var fisheye = new FisheyeCamera { MaxPsiDegrees = degrees / 2 };
            Place(fisheye, eye, lookAt, up);
            fisheye.ComputeUVW();
            var gpcm = RayTracer.Viewing.Gpcm.Fisheye(degrees);
            Place(gpcm, eye, lookAt, up);
            gpcm.Orient();
            for (var k = 0; k < 50; k++)
            {
                var pp = k == 0 ? new Point2D(0, 0) : RandomViewPoint(random);
                var hit = fisheye.GetRay(pp, vp, out var expected);
                Assert.Equal(hit, gpcm.GetRay(pp, vp, out var actual));
                if (!hit)
                    continue;
                seen++;
                AssertClose((Vector3D)expected.o, (Vector3D)actual.o);
                AssertClose(expected.d.Normalized(), actual.d);
                Assert.Equal(1, actual.d.Length, 12);
            }
        }
        // Both outcomes occur: the inscribed ellipse covers π/4 of the image.
        Assert.InRange(seen, 500, 900);
    }

    [Theory]
    [MemberData(nameof(Ups))]
    public void Cylindrical_gpcm_looks_through_the_unit_cylinder_about_image_up(Vector3D up)
    {
        var vp = Plane();
        var random = new Random(8);
        var fields = new[] { 360.0, 180.0, 90.0, 301.0 };
        for (var trial = 0; trial < 20; trial++)
        {
            var eye = RandomPoint(random);
            var lookAt = RandomPoint(random);
            var degrees = fields[trial % fields.Length];
            // The hand camera frame (u, v, w) and the closed form of the cylinder point as the truth.
            var frame = new PinholeCamera();
            Place(frame, eye, lookAt, up);
            frame.ComputeUVW();
            var gpcm = RayTracer.Viewing.Gpcm.Cylindrical(degrees, vp);
            Place(gpcm, eye, lookAt, up);
            gpcm.Orient();
            var maxAzimuth = degrees * Math.PI / 360;
            var height = 2 * maxAzimuth * 30 / 40;
            for (var k = 0; k < 50; k++)
            {
                var pp = RandomViewPoint(random);
                var azimuth = pp.x / 10 * maxAzimuth;
                var y = pp.y / 15 * height;
                var expected = (Math.Sin(azimuth) * frame.U + y * frame.V - Math.Cos(azimuth) * frame.W).Normalized();
                Assert.True(gpcm.GetRay(pp, vp, out var actual));
                AssertClose((Vector3D)eye, (Vector3D)actual.o);
                AssertClose(expected, actual.d);
            }
        }
    }

    [Fact]
    public void Full_cylindrical_gpcm_looks_backwards_at_both_side_edges()
    {
        var vp = Plane();
        var camera = RayTracer.Viewing.Gpcm.Cylindrical(360, vp);
        Place(camera, new Point3D(1, 2, 3), new Point3D(1, 2, 0), Vector3D.UnitY);
        camera.Orient();
        Assert.True(camera.GetRay(new Point2D(-10, 0), vp, out var left));
        Assert.True(camera.GetRay(new Point2D(10, 0), vp, out var right));
        AssertClose(Vector3D.UnitZ, left.d);
        AssertClose(Vector3D.UnitZ, right.d);
        Assert.True(camera.GetRay(new Point2D(5, 0), vp, out var quarter));
        AssertClose(Vector3D.UnitX, quarter.d);
    }

    [Fact]
    public void Polar_mapping_measures_turns_from_image_right_and_radius_to_the_inscribed_ellipse()
    {
        var vp = Plane();
        Assert.True(RayTracer.Viewing.Gpcm.PolarMap(new Point2D(0, 7.5), vp, out var u, out var v));
        Assert.Equal(0.25, u, 15);
        Assert.Equal(1, v, 15);
        Assert.True(RayTracer.Viewing.Gpcm.PolarMap(new Point2D(0, -3.75), vp, out u, out v));
        Assert.Equal(0.75, u, 15);
        Assert.Equal(0.5, v, 15);
        Assert.True(RayTracer.Viewing.Gpcm.PolarMap(new Point2D(-5, 0), vp, out u, out v));
        Assert.Equal(0.5, u, 15);
        Assert.False(RayTracer.Viewing.Gpcm.PolarMap(new Point2D(10, 7.5), vp, out _, out _));
    }

    [Fact]
    public void Polar_mapped_gpcm_sees_nothing_outside_the_inscribed_ellipse()
    {
        var camera = RayTracer.Viewing.Gpcm.Fisheye(180);
        camera.Orient();
        Assert.False(camera.GetRay(new Point2D(9.9, 7.4), Plane(), out _));
    }

    public static TheoryData<Func<object>> BadFields => new()
    {
        () => RayTracer.Viewing.Gpcm.Spherical(0),
        () => RayTracer.Viewing.Gpcm.Spherical(361),
        () => RayTracer.Viewing.Gpcm.Spherical(double.NaN),
        () => RayTracer.Viewing.Gpcm.Spherical(180, 0),
        () => RayTracer.Viewing.Gpcm.Spherical(180, 181),
        () => RayTracer.Viewing.Gpcm.Spherical(double.PositiveInfinity, 90),
        () => RayTracer.Viewing.Gpcm.Cylindrical(0, Plane()),
        () => RayTracer.Viewing.Gpcm.Cylindrical(360.5, Plane()),
        () => RayTracer.Viewing.Gpcm.Fisheye(-90),
        () => RayTracer.Viewing.Gpcm.Fisheye(400),
        () => RayTracer.Viewing.Gpcm.Fisheye(double.NaN),
    };

    [Theory]
    [MemberData(nameof(BadFields))]
    public void Bad_catalogue_field_of_view_throws_with_a_message(Func<object> make)
    {
        var error = Assert.Throws<ArgumentOutOfRangeException>(make);
        Assert.Contains("field of view", error.Message);
    }

    [Fact]
    public void Unknown_mapping_throws_with_a_message()
    {
        var error = Assert.Throws<ArgumentOutOfRangeException>(() => new RayTracer.Viewing.Gpcm(GpcmSurfaces.Cap(1), (GpcmMapping)7));
        Assert.Contains("uv mapping", error.Message);
    }
}
