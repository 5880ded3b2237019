using RayTracer.Maths;
using RayTracer.Viewing;

namespace RayTracer.Tests.Viewing;

public class Cameras_Rays
{
    private static ViewPlane Plane(int w = 100, int h = 80, double s = 1) => new() { HorizontalResolution = w, VerticalResolution = h, PixelSize = s };

    private static void AssertVector(Vector3D expected, Vector3D actual, int precision = 12)
    {
        Assert.Equal(expected.x, actual.x, precision);
        Assert.Equal(expected.y, actual.y, precision);
        Assert.Equal(expected.z, actual.z, precision);
    }

    [Fact]
    public void Camera_frame_is_orthonormal_and_right_handed()
    {
        var camera = new PinholeCamera { Eye = new Point3D(3, 4, 5), LookAt = new Point3D(-1, 0, 2), Up = new Vector3D(0, 1, 0) };
        camera.ComputeUVW();
        AssertVector((camera.Eye - camera.LookAt).Normalized(), camera.W);
        Assert.Equal(0, camera.U.Dot(camera.V), 12);
        Assert.Equal(0, camera.U.Dot(camera.W), 12);
        AssertVector(camera.W, camera.U.Cross(camera.V));
        Assert.Equal(0, camera.U.y, 12); // u stays horizontal when up is +y
    }

    [Fact]
    public void Looking_straight_down_still_gives_a_frame()
    {
        var camera = new PinholeCamera { Eye = new Point3D(0, 10, 0), LookAt = Point3D.Origin };
        camera.ComputeUVW();
        AssertVector(new Vector3D(0, 1, 0), camera.W);
        AssertVector(camera.W, camera.U.Cross(camera.V));
    }

    [Fact]
    public void Pinhole_rays_pass_through_the_view_plane_point()
    {
        var camera = new PinholeCamera { Eye = new Point3D(0, 0, 10), LookAt = Point3D.Origin, ViewDistance = 4 };
        camera.ComputeUVW();
        var vp = Plane();
        Assert.True(camera.GetRay(new Point2D(1.5, -2), vp, out var ray));
        Assert.Equal(camera.Eye, ray.o);
        // The view plane sits at z = 10 - 4; the ray must cross it at (1.5, -2).
        var t = (6 - ray.o.z) / ray.d.z;
        var p = ray.At(t);
        Assert.Equal(1.5, p.x, 12);
        Assert.Equal(-2, p.y, 12);
        Assert.Equal(1, ray.d.Length, 12);
    }

    [Fact]
    public void Pinhole_field_of_view_reaches_the_image_edge()
    {
        var vp = Plane(200, 100);
        var camera = new PinholeCamera { Eye = new Point3D(0, 0, 10), LookAt = Point3D.Origin };
        camera.ComputeUVW();
        camera.SetHorizontalFieldOfView(90, vp);
        camera.GetRay(new Point2D(100, 0), vp, out var ray);
        Assert.Equal(45.0, Math.Acos(-ray.d.z) * 180 / Math.PI, 9);
    }

    [Fact]
    public void Orthographic_rays_are_parallel_and_start_on_the_view_plane()
    {
        var camera = new OrthographicCamera { Eye = new Point3D(1, 2, 10), LookAt = new Point3D(1, 2, 0) };
        camera.ComputeUVW();
        camera.GetRay(new Point2D(3, -4), Plane(), out var ray);
        AssertVector(new Vector3D(0, 0, -1), ray.d);
        Assert.Equal(new Point3D(4, -2, 10), ray.o);
    }

    [Fact]
    public void Thin_lens_rays_from_every_lens_point_meet_on_the_focal_plane()
    {
        var camera = new ThinLensCamera { Eye = new Point3D(0, 0, 20), LookAt = Point3D.Origin, ViewDistance = 5, FocalDistance = 15, LensRadius = 2 };
        camera.ComputeUVW();
        var pp = new Point2D(1, 0.5);
        // A pinhole ray through pp hits the focal plane (z = 5) at pp scaled by f/d.
        var expected = new Point3D(3, 1.5, 5);
        foreach (var lens in new[] { new Point2D(0, 0), new Point2D(1, 0), new Point2D(-0.3, 0.8) })
        {
            var ray = camera.RayThrough(pp, lens);
            Assert.Equal(20, ray.o.z, 12);
            var p = ray.At((5 - ray.o.z) / ray.d.z);
            Assert.Equal(expected.x, p.x, 10);
            Assert.Equal(expected.y, p.y, 10);
        }
        Assert.Equal(new Point3D(2, 0, 20), camera.RayThrough(pp, new Point2D(1, 0)).o);
    }

    [Fact]
    public void Fisheye_maps_radius_to_angle_and_sees_nothing_outside_its_circle()
    {
        var vp = Plane(100, 100);
        var camera = new FisheyeCamera { Eye = Point3D.Origin, LookAt = new Point3D(0, 0, -1), MaxPsiDegrees = 90 };
        camera.ComputeUVW();
        camera.GetRay(new Point2D(0, 0), vp, out var centre);
        AssertVector(new Vector3D(0, 0, -1), centre.d);
        camera.GetRay(new Point2D(25, 0), vp, out var half); // half way to the rim: ψ = 45°
        AssertVector(new Vector3D(Math.Sqrt(0.5), 0, -Math.Sqrt(0.5)), half.d);
        camera.GetRay(new Point2D(0, 50), vp, out var rim);
        AssertVector(new Vector3D(0, 1, 0), rim.d);
        Assert.False(camera.GetRay(new Point2D(40, 40), vp, out _));
    }

    [Fact]
    public void Spherical_panorama_covers_all_azimuths()
    {
        var vp = Plane(200, 100);
        var camera = new SphericalCamera { Eye = Point3D.Origin, LookAt = new Point3D(0, 0, -1) };
        camera.ComputeUVW();
        camera.GetRay(new Point2D(0, 0), vp, out var ahead);
        AssertVector(new Vector3D(0, 0, -1), ahead.d);
        camera.GetRay(new Point2D(50, 0), vp, out var right); // λ = 90°
        AssertVector(new Vector3D(1, 0, 0), right.d);
        camera.GetRay(new Point2D(100, 0), vp, out var behind); // λ = 180°
        AssertVector(new Vector3D(0, 0, 1), behind.d);
        camera.GetRay(new Point2D(0, 50), vp, out var up); // ψ = 90°
        AssertVector(new Vector3D(0, 1, 0), up.d);
    }

    [Fact]
    public void Stereo_pair_separates_the_eyes_by_the_stereo_angle()
    {
        var stereo = new StereoCamera(new PinholeCamera(), new PinholeCamera())
        {
            Eye = new Point3D(0, 0, 10), LookAt = Point3D.Origin, StereoAngleDegrees = 10, PixelGap = 4,
        };
        stereo.SetUpCameras();
        var x = 10 * Math.Tan(MathConstants.ToRadians(5));
        Assert.Equal(-x, stereo.Left.Eye.x, 12);
        Assert.Equal(x, stereo.Right.Eye.x, 12);
        AssertVector(new Vector3D(0, 0, 1), stereo.Left.W);
        Assert.Equal(2 * 100 + 4, stereo.ImageWidth(Plane()));
    }
}
