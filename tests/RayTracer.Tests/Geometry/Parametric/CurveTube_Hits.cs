using RayTracer.Geometry.Parametric;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Tests.Geometry.Parametric;

public class CurveTube_Hits
{
    private const double Tolerance = 1e-3;
    private const double Radius = 0.1;

    [Fact]
    public void Rays_at_a_circle_tube_hit_at_the_analytic_distance_with_the_analytic_normal()
    {
        var tube = new CurveTube(new ClosedForms.Circle(1), Radius, Tolerance);
        var random = new Random(9);
        var sr = new ShadingRecord();
        for (var k = 0; k < 300; k++)
        {
            var a = 2 * Math.PI * random.NextDouble();
            var onCurve = new Point3D(Math.Cos(a), Math.Sin(a), 0);
            var radial = new Vector3D(Math.Cos(a), Math.Sin(a), 0);

            // From above: the top of the tube is one radius above the curve.
            Assert.True(tube.Hit(new Ray(onCurve + new Vector3D(0, 0, 2), new Vector3D(0, 0, -1)), out var t, sr));
            Assert.True(Math.Abs(t - (2 - Radius)) <= Tolerance, $"from above: {t}");
            Assert.True(Math.Acos(Math.Min(1, sr.Normal.z)) < 0.02, $"normal {sr.Normal}");

            // From outside in the plane: the axis is inscribed in the circle, within the tolerance of it.
            Assert.True(tube.Hit(new Ray(onCurve + 2 * radial, -radial), out t, sr));
            Assert.InRange(t, 2 - Radius - 1e-9, 2 - Radius + Tolerance);
            Assert.True(Math.Acos(Math.Min(1, sr.Normal.Dot(radial))) < 0.05, $"normal {sr.Normal} vs {radial}");
        }
    }

    [Fact]
    public void A_helix_tube_is_cylinders_between_samples_and_a_sphere_at_every_sample_in_one_hierarchy()
    {
        var helix = new ClosedForms.Helix(1, 2, 3);
        var tube = new CurveTube(helix, 0.05, Tolerance);
        var joints = tube.Samples.Points.Count;
        Assert.Equal(2 * joints - 1, tube.PrimitiveCount);

        // A ray across the axis at any sample and any parameter between samples meets the tube.
        var sr = new ShadingRecord();
        var random = new Random(4);
        for (var k = 0; k < 200; k++)
        {
            var p = helix.PointAt(random.NextDouble());
            var centre = new Point3D(p.x, p.y, p.z);
            var outward = new Vector3D(p.x, p.y, 0).Normalized();
            Assert.True(tube.Hit(new Ray(centre + 0.5 * outward, -outward), out var t, sr));
            Assert.InRange(t, 0.45 - 1e-9, 0.45 + Tolerance);
        }
    }

    [Fact]
    public void A_tube_needs_a_positive_radius()
    {
        var error = Assert.Throws<ArgumentOutOfRangeException>(() => new CurveTube(new ClosedForms.Circle(1), 0, Tolerance));
        Assert.Contains("positive finite radius", error.Message);
    }

    [Fact]
    public void Material_reaches_every_part()
    {
        var tube = new CurveTube(new ClosedForms.Circle(1), Radius, 1e-2);
        var material = RayTracer.Factories.MaterialFactory.Matte(RayTracer.Colors.RGBColor.White);
        tube.Material = material;
        var sr = new ShadingRecord();
        Assert.True(tube.Hit(new Ray(new Point3D(1, 0, 2), new Vector3D(0, 0, -1)), out _, sr));
        Assert.Same(material, sr.Material);
    }
}
