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

public class WhittedIntegrator_MaximumDepth
{
    [Theory]
    [InlineData(0)]
    [InlineData(1)]
    [InlineData(3)]
    [InlineData(6)]
    public void Facing_mirrors_sum_a_geometric_series_cut_at_the_maximum_depth(int maxDepth)
    {
        // Between two parallel mirrors every bounce adds the ambient term ka·La and scales the rest by kr,
        // so a ray that may recurse to depth D carries ka·La · Σ_{k=0..D} kr^k.
        const double ka = 0.3, kr = 0.5, la = 1.0;
        var world = TestScenes.OrthographicWorld(1, 0.01, w => new WhittedIntegrator(w));
        world.ViewPlane.MaxDepth = maxDepth;
        var camera = new OrthographicCamera { Eye = new Point3D(0, 0, 1), LookAt = Point3D.Origin };
        camera.ComputeUVW();
        world.Camera = camera;
        world.AmbientLight = new AmbientLight(la);
        world.BackgroundColor = new RGBColor(100, 100, 100); // must never be seen
        var mirror = new Reflective(ka, 0, RGBColor.White, 0, 10, kr, RGBColor.White);
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 0, 1)) { Material = mirror });
        world.Add(new Plane(new Point3D(0, 0, 2), new Normal3D(0, 0, -1)) { Material = mirror });

        var pixel = new Renderer().Render(world)[0, 0];
        var expected = ka * la * (1 - Math.Pow(kr, maxDepth + 1)) / (1 - kr);
        Assert.Equal(expected, pixel.r, 12);
    }
}
