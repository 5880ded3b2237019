using RayTracer.Geometry.Universal;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Geometry.Universal;

public class Cylinder_Hits
{
    private static readonly Point3D Base = new(1, -1, 2);
    private static readonly Vector3D Axis = new(1, 2, 2); // length 3

    private static double Distance(Point3D p, out double h)
    {
        var a = Axis.Normalized();
        var rel = p - Base;
        h = Vector3D.Dot(rel, a);
        return (rel - h * a).Length;
    }

    [Fact]
    public void Open_cylinder_in_any_orientation_agrees_with_brute_force()
    {
        var cyl = new Cylinder(Base, Axis, 0.75);
        double F(Point3D p) => Distance(p, out _) - 0.75;
        bool Accept(Point3D p)
        {
            Distance(p, out double h);
            return h >= 0 && h <= 3;
        }

        var random = new SeededRandom(71);
        var sr = new ShadingRecord();
        int hits = 0;
        for (int n = 0; n < 300; n++)
        {
            var ray = ImplicitSurfaceMarch.RandomRayTowards(random, 6, 2);
            ray.o += new Vector3D(1.5, 0, 3);
            double? expected = ImplicitSurfaceMarch.FirstRoot(F, ray, 20, 2e-3, Accept);
            bool hit = cyl.Hit(ray, out double t, sr);
            Assert.Equal(expected.HasValue, hit);
            if (hit)
            {
                hits++;
                Assert.Equal(expected!.Value, t, 6);
                Assert.Equal(1, sr.Normal.Length, 12);
                Assert.True(sr.Normal.Dot(ray.d) <= 0, "open tube normals face the viewer");
            }
        }

        Assert.True(hits > 50);
    }

    [Fact]
    public void Capped_cylinder_hits_the_cap_along_the_axis()
    {
        var cyl = new Cylinder(Base, Axis, 0.75, capped: true);
        var a = Axis.Normalized();
        var sr = new ShadingRecord();
        Assert.True(cyl.Hit(new Ray(Base - 2 * a, a), out double t, sr));
        Assert.Equal(2, t, 12);
        Assert.True((sr.Normal.ToVector() + a).Length < 1e-12);
        Assert.True(cyl.Hit(new Ray(Base + 5 * a + new Vector3D(0.01, 0, 0), -a), out t, sr));
        Assert.Equal(2, t, 2);
        Assert.True((sr.Normal.ToVector() - a).Length < 1e-12);
    }
}
