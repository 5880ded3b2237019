using RayTracer.Factories;
using RayTracer.Geometry.Parametric;
using RayTracer.Maths;
using RayTracer.Scenes;
using RayTracer.Tracing;
using RayTracer.Viewing;
using Twister;

namespace RayTracer.Tests.Viewing.Gpcm;

public class Gpcm_PlacedSurface
{
    private static readonly ViewPlane Plane = new() { HorizontalResolution = 48, VerticalResolution = 24, PixelSize = 0.5 };

    private static Vector3D ToVector(TwistablePoint p) => new(p.x, p.y, p.z);

    private static Vector3D ToVector(TwistableVector v) => new(v.x, v.y, v.z);

    [Theory]
    [InlineData("spherical")]
    [InlineData("cylindrical")]
    [InlineData("conic")]
    [InlineData("rectangular")]
    public void Rays_from_the_surface_start_on_the_placed_surface(string name)
    {
        Assert.True(CameraCatalog.TryFind(name, out var choice));
        var random = new Random(3);
        for (var trial = 0; trial < 10; trial++)
        {
            var eye = new Point3D(20 * random.NextDouble() - 10, 20 * random.NextDouble() - 10, 20 * random.NextDouble() - 10);
            var lookAt = eye + new Vector3D(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
            var camera = (RayTracer.Viewing.Gpcm)choice.Create(choice.DefaultDegrees, Plane, eye, lookAt, new Vector3D(0.2, 1, -0.3));
            camera.RayOrigin = GpcmRayOrigin.Surface;
            camera.SurfaceScale = 0.5 + 3 * random.NextDouble();
            var placed = camera.PlacedSurface();
            for (var k = 0; k < 20; k++)
            {
                var pp = new Point2D((random.NextDouble() - 0.5) * 24, (random.NextDouble() - 0.5) * 12);
                Assert.True(camera.GetRay(pp, Plane, out var ray));
                var (u, v) = RayTracer.Viewing.Gpcm.RectangularMap(pp, Plane);
                var expected = ToVector(placed.PointAt(u, v));
                Assert.True(((Vector3D)ray.o - expected).Length <= 1e-9 * (1 + expected.Length), $"{name}: {ray.o} vs {expected}");
                // The ray leaves the eye's side of the surface along the line from the eye.
                var fromEye = ((Vector3D)ray.o - (Vector3D)eye).Normalized();
                Assert.True((fromEye - ray.d).Length <= 1e-9);
            }
        }
    }

    [Fact]
    public void Placed_normals_are_the_rest_normals_turned_into_the_world()
    {
        var camera = RayTracer.Viewing.Gpcm.Spherical(360);
        camera.Eye = new Point3D(1, 2, 3);
        camera.LookAt = new Point3D(4, 0, -1);
        camera.Up = new Vector3D(0, 0, 1);
        camera.SurfaceScale = 2;
        var orientation = camera.Orient();
        var placed = camera.PlacedSurface();
        foreach (var (u, v) in new[] { (0.3, 0.4), (0.7, 0.6), (0.5, 0.5) })
        {
            // On a sphere about the eye the outward normal points away from the eye.
            var n = placed.NormalAt(u, v);
            var normal = new Vector3D(n.x, n.y, n.z).Normalized();
            var radial = (ToVector(placed.PointAt(u, v)) - (Vector3D)orientation.Eye).Normalized();
            Assert.True(Math.Abs(Math.Abs(normal.Dot(radial)) - 1) < 1e-9);
            Assert.Equal(2, (ToVector(placed.PointAt(u, v)) - (Vector3D)orientation.Eye).Length, 1e-12);
        }
    }

    [Fact]
    public void An_unoriented_camera_has_no_placed_surface()
    {
        var camera = RayTracer.Viewing.Gpcm.Fisheye(180);
        Assert.Throws<InvalidOperationException>(() => camera.PlacedSurface());
    }

    [Fact]
    public void Iso_parameter_curves_follow_the_surface_with_its_tangents()
    {
        var sphere = GpcmSurfaces.Sphere(1.2, 0.6);
        var along = IsoParameterCurve.AtV(sphere, 0.25);
        var across = IsoParameterCurve.AtU(sphere, 0.75);
        foreach (var t in new[] { 0.0, 0.4, 1.0 })
        {
            Assert.Equal(ToVector(sphere.PointAt(t, 0.25)), ToVector(along.PointAt(t)));
            Assert.Equal(ToVector(sphere.PointAt(0.75, t)), ToVector(across.PointAt(t)));
            // On the sphere's latitude circle ψ, the point moves at 2 λmax cos ψ per unit u.
            var psi = (2 * 0.25 - 1) * 0.6;
            Assert.Equal(2 * 1.2 * Math.Cos(psi), ToVector(along.TangentAt(t)).Length, 1e-6);
            Assert.Equal(2 * 0.6, ToVector(across.TangentAt(t)).Length, 1e-6);
        }
        Assert.Throws<ArgumentOutOfRangeException>(() => IsoParameterCurve.AtU(sphere, 1.5));
    }

    [Theory]
    [InlineData("gpcm-rectangular-layout")]
    [InlineData("gpcm-fisheye-layout")]
    public void Layout_scenes_look_at_the_gallerys_eye_from_outside_and_see_the_drawn_camera(string name)
    {
        Assert.True(SceneFactory.TryCreate(name, out var scene));
        var world = scene.Build(new SceneSettings { Width = 32, Height = 24, SamplesPerPixel = 1 });
        var outside = Assert.IsType<PinholeCamera>(world.Camera);
        // The ray through the image centre passes within the drawn surface's reach of the eye.
        Assert.True(outside.GetRay(new Point2D(0, 0), world.ViewPlane, out var ray));
        var toEye = (Vector3D)RayTracer.Scenes.Gpcm.GpcmGallery.Eye - (Vector3D)ray.o;
        var miss = (toEye - toEye.Dot(ray.d) * ray.d).Length;
        Assert.True(miss < 1.5, $"the view misses the eye by {miss}");
        // A ray aimed straight at the eye stops at the drawn camera (its eye ball or a wire of its
        // surface, 1.5 across), not at the gallery behind it.
        var aimed = new Ray(outside.Eye, toEye.Normalized());
        var record = new ShadingRecord();
        Assert.True(world.HitObjects(aimed, record));
        Assert.True(((Vector3D)record.HitPoint - (Vector3D)RayTracer.Scenes.Gpcm.GpcmGallery.Eye).Length <= 1.6);
    }
}
