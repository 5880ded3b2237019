using RayTracer.Maths;
using RayTracer.Viewing;

namespace RayTracer.Tests.Viewing.Gpcm;

public class Gpcm_Rays
{
    private static ViewPlane Plane() => new() { HorizontalResolution = 40, VerticalResolution = 30, PixelSize = 0.5 };

    private static Vector3D RandomVector(Random random, double scale) =>
        new(scale * (2 * random.NextDouble() - 1), scale * (2 * random.NextDouble() - 1), scale * (2 * random.NextDouble() - 1));

    private static Point3D RandomPoint(Random random) => Point3D.Origin + RandomVector(random, 50);

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

    [Theory]
    [MemberData(nameof(Ups))]
    public void Rectangular_gpcm_gives_the_pinhole_cameras_primary_rays(Vector3D up)
    {
        var vp = Plane();
        var random = new Random(12);
        for (var trial = 0; trial < 20; trial++)
        {
            var eye = RandomPoint(random);
            var lookAt = RandomPoint(random);
            var fov = 20 + 140 * random.NextDouble();
            var pinhole = new PinholeCamera { Eye = eye, LookAt = lookAt, Up = up };
            pinhole.SetHorizontalFieldOfView(fov, vp);
            pinhole.ComputeUVW();
            var gpcm = RayTracer.Viewing.Gpcm.Rectangular(fov, vp);
            gpcm.Eye = eye;
            gpcm.LookAt = lookAt;
            gpcm.Up = up;
            gpcm.Orient();
            for (var k = 0; k < 50; k++)
            {
                var pp = new Point2D((random.NextDouble() - 0.5) * 20, (random.NextDouble() - 0.5) * 15);
                Assert.True(pinhole.GetRay(pp, vp, out var expected));
                Assert.True(gpcm.GetRay(pp, vp, out var actual));
                AssertClose((Vector3D)expected.o, (Vector3D)actual.o);
                AssertClose(expected.d, actual.d);
                Assert.Equal(1, actual.d.Length, 12);
            }
        }
    }

    [Fact]
    public void Look_at_point_projects_to_the_image_centre_and_up_to_image_up()
    {
        var vp = Plane();
        var random = new Random(7);
        for (var trial = 0; trial < 200; trial++)
        {
            var up = RandomVector(random, 3);
            var eye = RandomPoint(random);
            var n = up.Normalized();
            // Every fourth target lies almost straight above or below the eye, within 1e-9 rad of ±up.
            var lookAt = trial % 4 == 0
                ? eye + (trial % 8 == 0 ? 1 : -1) * 10 * (n + 1e-9 * RandomVector(random, 1))
                : RandomPoint(random);
            var camera = RayTracer.Viewing.Gpcm.Rectangular(60, vp);
            camera.Eye = eye;
            camera.LookAt = lookAt;
            camera.Up = up;
            var frame = camera.Orient();

            Assert.True(camera.GetRay(new Point2D(0, 0), vp, out var centre));
            AssertClose((lookAt - eye).Normalized(), centre.d);
            AssertClose(-centre.d, frame.Back);
            AssertClose(frame.Back, frame.Right.Cross(frame.Up));
            Assert.Equal(1, frame.Right.Length, 12);
            Assert.Equal(1, frame.Up.Length, 12);
            // Up seen through the camera points straight up the image: no sideways part, a positive upward one.
            Assert.Equal(0, frame.Right.Dot(n), 12);
            Assert.True(frame.Up.Dot(n) > 0, $"image up {frame.Up} leans away from {n}");
        }
    }

    [Theory]
    [InlineData(1.0)]
    [InlineData(-1.0)]
    public void Looking_exactly_along_up_keeps_the_look_at_point_in_the_centre(double sign)
    {
        var vp = Plane();
        var camera = RayTracer.Viewing.Gpcm.Rectangular(60, vp);
        camera.Eye = new Point3D(1, 2, 3);
        camera.Up = new Vector3D(0, 0, 2);
        camera.LookAt = camera.Eye + sign * new Vector3D(0, 0, 5);
        var frame = camera.Orient();
        Assert.True(camera.GetRay(new Point2D(0, 0), vp, out var centre));
        AssertClose(new Vector3D(0, 0, sign), centre.d);
        AssertClose(frame.Back, frame.Right.Cross(frame.Up));
        Assert.Equal(0, frame.Right.z, 12);
    }

    [Fact]
    public void Rotor_onto_takes_a_unit_vector_onto_another_even_when_nearly_or_exactly_opposite()
    {
        var random = new Random(3);
        for (var trial = 0; trial < 100; trial++)
        {
            var a = RandomVector(random, 1).Normalized();
            var axis = a.Cross(RandomVector(random, 1)).Normalized();
            var b = trial switch
            {
                < 40 => RandomVector(random, 1).Normalized(),
                < 70 => (-a + 1e-9 * RandomVector(random, 1)).Normalized(),
                _ => -a,
            };
            var frame = Rotated(GpcmOrientation.RotorOnto(a, b, axis));
            AssertClose(b, frame(a));
            if (trial >= 70)
                AssertClose(axis, frame(axis)); // the exact opposite turns half way about the fallback axis
        }
    }

    private static Func<Vector3D, Vector3D> Rotated(Rotor3D r)
    {
        Assert.Equal(1, r.s * r.s + r.xy * r.xy + r.yz * r.yz + r.zx * r.zx, 12);
        // R x R~ expanded by hand with the rotation matrix of a unit rotor (thesis 7.6 in its corrected form).
        double w = r.s, x = -r.yz, y = -r.zx, z = -r.xy;
        return v => new Vector3D(
            (1 - 2 * (y * y + z * z)) * v.x + 2 * (x * y - w * z) * v.y + 2 * (x * z + w * y) * v.z,
            2 * (x * y + w * z) * v.x + (1 - 2 * (x * x + z * z)) * v.y + 2 * (y * z - w * x) * v.z,
            2 * (x * z - w * y) * v.x + 2 * (y * z + w * x) * v.y + (1 - 2 * (x * x + y * y)) * v.z);
    }

    [Fact]
    public void Eye_on_the_look_at_point_throws_with_a_message()
    {
        var camera = RayTracer.Viewing.Gpcm.Rectangular(60, Plane());
        camera.Eye = new Point3D(1, 2, 3);
        camera.LookAt = new Point3D(1, 2, 3);
        var error = Assert.Throws<ArgumentException>(() => camera.Orient());
        Assert.Contains("must be distinct", error.Message);
    }

    [Fact]
    public void Zero_up_direction_throws_with_a_message()
    {
        var camera = RayTracer.Viewing.Gpcm.Rectangular(60, Plane());
        camera.Up = new Vector3D(0, 0, 0);
        var error = Assert.Throws<ArgumentException>(() => camera.Orient());
        Assert.Contains("up direction", error.Message);
    }

    [Theory]
    [InlineData(0.0)]
    [InlineData(180.0)]
    [InlineData(double.NaN)]
    public void Bad_field_of_view_throws_with_a_message(double degrees)
    {
        var error = Assert.Throws<ArgumentOutOfRangeException>(() => RayTracer.Viewing.Gpcm.Rectangular(degrees, Plane()));
        Assert.Contains("field of view", error.Message);
    }

    [Fact]
    public void Rays_before_orienting_throw_with_a_message()
    {
        var camera = RayTracer.Viewing.Gpcm.Rectangular(60, Plane());
        var error = Assert.Throws<InvalidOperationException>(() => camera.GetRay(new Point2D(0, 0), Plane(), out _));
        Assert.Contains("Orient()", error.Message);
    }
}
