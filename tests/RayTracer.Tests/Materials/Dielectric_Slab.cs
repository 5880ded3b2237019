using RayTracer.Colors;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tests.Tracing;
using RayTracer.Tracing;
using RayTracer.Viewing;

namespace RayTracer.Tests.Materials;

public class Dielectric_Slab
{
    [Theory]
    [InlineData(1.0)]
    [InlineData(0.5)]
    [InlineData(0.2)]
    public void Radiance_through_a_slab_at_normal_incidence_matches_the_multiple_reflection_sum(double filter)
    {
        // At normal incidence every path ends in the background (radiance 1). With Fresnel reflectance R and
        // Beer transmittance a for one crossing of the unit-thick slab, a path either reflects at the front (R)
        // or enters, crosses n times reflecting n - 1 times inside, and leaves: weight (1 - R)² R^(n-1) a^n.
        // Summed: R + (1 - R)² a / (1 - R a), which is 1 for a clear slab (energy is conserved).
        const double ior = 1.5;
        var r = Math.Pow((ior - 1) / (ior + 1), 2);
        var world = TestScenes.OrthographicWorld(1, 0.01, w => new WhittedIntegrator(w));
        world.ViewPlane.MaxDepth = 60;
        world.ViewPlane.MinimumThroughput = 0; // the series is checked to 9 places, so trace every ray
        world.BackgroundColor = RGBColor.White;
        world.Add(new Box(new Point3D(-10, -10, -0.5), new Point3D(10, 10, 0.5))
        {
            Material = new Dielectric(ior, 1.0, new RGBColor(filter, filter, filter)),
        });
        var pixel = new Renderer().Render(world)[0, 0];
        var expected = r + (1 - r) * (1 - r) * filter / (1 - r * filter);
        Assert.Equal(expected, pixel.g, 9);
    }
}
