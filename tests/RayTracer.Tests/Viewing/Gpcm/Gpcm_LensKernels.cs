using RayTracer.Maths;
using RayTracer.Viewing;

namespace RayTracer.Tests.Viewing.Gpcm;

/// <summary>
/// The catalogue's generated lens kernels against the general way every surface takes: the Twister
/// cascade evaluated at (u, v), then turned into the world and normalized.
/// </summary>
public class Gpcm_LensKernels
{
    private static readonly ViewPlane Plane = new() { HorizontalResolution = 64, VerticalResolution = 36, PixelSize = 0.25 };

    public static TheoryData<string> Cameras => new() { "rectangular", "spherical", "cylindrical", "conic", "fisheye", "fisheye-narrow", "spherical-polar" };

    private static RayTracer.Viewing.Gpcm Create(string name) => name switch
    {
        "rectangular" => RayTracer.Viewing.Gpcm.Rectangular(75, Plane),
        "spherical" => RayTracer.Viewing.Gpcm.Spherical(300, 150),
        "cylindrical" => RayTracer.Viewing.Gpcm.Cylindrical(200, Plane),
        "conic" => RayTracer.Viewing.Gpcm.Conic(360, Plane, 40),
        "fisheye" => RayTracer.Viewing.Gpcm.Fisheye(360),
        "fisheye-narrow" => RayTracer.Viewing.Gpcm.Fisheye(50),
        // A lens under the other mapping has no kernel: the general way serves it.
        "spherical-polar" => new RayTracer.Viewing.Gpcm(GpcmSurfaces.Sphere(2, 1), GpcmMapping.Polar),
        _ => throw new ArgumentOutOfRangeException(nameof(name)),
    };

    private static Vector3D RandomVector(Random random, double scale) =>
        new(scale * (2 * random.NextDouble() - 1), scale * (2 * random.NextDouble() - 1), scale * (2 * random.NextDouble() - 1));

    [Theory]
    [MemberData(nameof(Cameras))]
    public void Kernel_rays_equal_the_cascades_rays(string name)
    {
        var random = new Random(name.Length * 97 + 5);
        var width = Plane.HorizontalResolution * Plane.PixelSize;
        var height = Plane.VerticalResolution * Plane.PixelSize;
        for (var trial = 0; trial < 12; trial++)
        {
            var camera = Create(name);
            camera.Eye = Point3D.Origin + RandomVector(random, 100);
            camera.LookAt = Point3D.Origin + RandomVector(random, 100);
            camera.Up = trial % 3 == 0 ? Vector3D.UnitY : RandomVector(random, 1);
            camera.RayDirection = trial % 4 == 1 ? GpcmRayDirection.Inward : GpcmRayDirection.Outward;
            camera.Orient();
            for (var k = 0; k < 60; k++)
            {
                // The whole view plane, a little beyond its edges, its centre and its corners.
                var pp = k switch
                {
                    0 => new Point2D(0, 0),
                    1 => new Point2D(width / 2, height / 2),
                    2 => new Point2D(-width / 2, height / 2),
                    3 => new Point2D(0, -height / 2),
                    _ => new Point2D((random.NextDouble() - 0.5) * width * 1.1, (random.NextDouble() - 0.5) * height * 1.1),
                };
                camera.EvaluateThroughCascade = false;
                var kernelSees = camera.GetRay(pp, Plane, out var kernel);
                camera.EvaluateThroughCascade = true;
                var cascadeSees = camera.GetRay(pp, Plane, out var cascade);
                Assert.Equal(cascadeSees, kernelSees);
                if (!cascadeSees) continue;
                Assert.True(((Vector3D)kernel.o - (Vector3D)cascade.o).Length <= 1e-12, $"{name} at {pp}: origin {kernel.o} vs {cascade.o}");
                Assert.True((kernel.d - cascade.d).Length <= 1e-12, $"{name} at {pp}: direction {kernel.d} vs {cascade.d}");
                Assert.Equal(1, kernel.d.Length, 1e-14);
            }
        }
    }

    [Fact]
    public void Rays_from_the_surface_take_the_general_way_and_start_on_the_scaled_surface()
    {
        var camera = RayTracer.Viewing.Gpcm.Spherical(360);
        camera.Eye = new Point3D(1, 2, 3);
        camera.LookAt = new Point3D(1, 2, -5);
        camera.Up = Vector3D.UnitY;
        camera.RayOrigin = GpcmRayOrigin.Surface;
        camera.SurfaceScale = 4;
        camera.Orient();
        Assert.True(camera.GetRay(new Point2D(3, -1), Plane, out var ray));
        Assert.Equal(4, ((Vector3D)ray.o - (Vector3D)camera.Eye).Length, 1e-12);
        Assert.True(((Vector3D)ray.o - (Vector3D)camera.Eye - 4 * ray.d).Length <= 1e-12);
    }
}
