using RayTracer.Colors;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tests.Tracing;
using RayTracer.Tracing;
using RayTracer.Viewing;

namespace RayTracer.Tests.Integrators;

public class RayCastIntegrator_LambertianSphere
{
    [Fact]
    public void Pixels_match_the_analytic_radiance_of_a_point_lit_lambertian_sphere()
    {
        var world = TestScenes.OrthographicWorld(21, 0.1, w => new RayCastIntegrator(w));
        const double kd = 0.8;
        var cd = new RGBColor(1, 0.5, 0.25);
        world.Add(new Sphere(Point3D.Origin, 1) { Material = new Matte(0, kd, cd) });
        var lightPosition = new Point3D(3, 4, 10);
        const double ls = 100;
        world.Add(new PointLight(lightPosition, ls) { FalloffPower = 2 });

        var image = new Renderer(new RenderOptions { Threads = 1 }).Render(world);

        var checkedPixels = 0;
        for (var row = 0; row < 21; row++)
        for (var column = 0; column < 21; column++)
        {
            var (x, y) = TestScenes.PixelCentre(world.ViewPlane, column, row);
            var r2 = x * x + y * y;
            if (r2 >= 0.95)
                continue;
            // Orthographic ray along -z hits the unit sphere at z = sqrt(1 - x² - y²) with normal = point.
            var p = new Point3D(x, y, Math.Sqrt(1 - r2));
            var toLight = lightPosition - p;
            var cosTheta = Math.Max(0, toLight.Normalized().Dot(p.ToVector()));
            // L = (kd·cd/π) · (ls / d²) · cos θ for a Lambertian surface under an inverse-square point light.
            var expected = kd * cd * (1 / Math.PI) * (ls / toLight.LengthSquared * cosTheta);
            var actual = image[column, row];
            Assert.Equal(expected.r, actual.r, 9);
            Assert.Equal(expected.g, actual.g, 9);
            Assert.Equal(expected.b, actual.b, 9);
            checkedPixels++;
        }
        Assert.True(checkedPixels > 200);
        Assert.Equal(RGBColor.Black, image[0, 0]); // background
    }

    [Fact]
    public void A_blocker_casts_a_shadow_unless_shadows_are_switched_off()
    {
        RGBColor Centre(bool lightShadows, bool blockerShadows)
        {
            var world = TestScenes.OrthographicWorld(3, 0.01, w => new RayCastIntegrator(w));
            world.Add(new Plane(Point3D.Origin, new Normal3D(0, 0, 1)) { Material = new Matte(0, 1, RGBColor.White) });
            world.Add(new Sphere(new Point3D(0, 0, 3), 0.5) { Material = new Matte(), CastsShadows = blockerShadows });
            world.Add(new PointLight(new Point3D(0, 0, 6)) { CastsShadows = lightShadows });
            // Look from below the blocker so the camera sees the plane: move the eye inside the gap.
            var camera = new OrthographicCamera { Eye = new Point3D(0, 0, 1), LookAt = Point3D.Origin };
            camera.ComputeUVW();
            world.Camera = camera;
            return new Renderer().Render(world)[1, 1];
        }
        Assert.Equal(RGBColor.Black, Centre(true, true));
        Assert.Equal(1 / Math.PI, Centre(false, true).r, 12);
        Assert.Equal(1 / Math.PI, Centre(true, false).r, 12);
    }

    [Fact]
    public void Directional_and_ambient_light_add_up()
    {
        var world = TestScenes.OrthographicWorld(1, 0.01, w => new RayCastIntegrator(w));
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 0, 1)) { Material = new Matte(0.5, 0.6, new RGBColor(1, 1, 0)) });
        world.AmbientLight = new AmbientLight(0.4);
        world.Add(new DirectionalLight(new Vector3D(0, 1, 1), 2.0));
        var pixel = new Renderer().Render(world)[0, 0];
        var expected = 0.5 * 0.4 + 0.6 / Math.PI * 2.0 * Math.Sqrt(0.5);
        Assert.Equal(expected, pixel.r, 12);
        Assert.Equal(0, pixel.b, 12);
    }
}
