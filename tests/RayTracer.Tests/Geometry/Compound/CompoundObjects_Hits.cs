using RayTracer.Geometry.Compound;
using RayTracer.Geometry.Universal;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Geometry.Compound;

public class CompoundObjects_Hits
{
    [Fact]
    public void Compound_returns_the_nearest_part_and_its_shading()
    {
        var near = new Sphere(new Point3D(0, 0, 2), 1);
        var far = new Sphere(new Point3D(0, 0, -2), 1.5);
        var compound = new CompoundObject();
        compound.Add(far);
        compound.Add(near);
        var sr = new ShadingRecord();
        Assert.True(compound.Hit(new Ray(new Point3D(0, 0, 10), new Vector3D(0, 0, -1)), out double t, sr));
        Assert.Equal(7, t, 12);
        Assert.Equal(new Normal3D(0, 0, 1), sr.Normal);
        // Past the near sphere only the far one remains.
        Assert.True(compound.Hit(new Ray(new Point3D(0.5, 1.2, 10), new Vector3D(0, 0, -1)), out t, sr));
        Assert.Equal(10 - (-2 + Math.Sqrt(2.25 - 0.25 - 1.44)), t, 9);
    }

    [Fact]
    public void Solid_cylinder_is_closed_with_outward_normals()
    {
        var solid = new SolidCylinder(-1, 2, 1);
        var sr = new ShadingRecord();
        Assert.True(solid.Hit(new Ray(new Point3D(0.3, 10, 0.2), new Vector3D(0, -1, 0)), out double t, sr));
        Assert.Equal(8, t, 12);
        Assert.Equal(new Normal3D(0, 1, 0), sr.Normal);
        Assert.True(solid.Hit(new Ray(new Point3D(0, 0, 0), new Vector3D(1, 0, 0)), out t, sr));
        Assert.Equal(1, t, 12);
        Assert.Equal(1, sr.Normal.x, 12); // outward from inside, too
    }

    [Fact]
    public void Beveled_box_matches_its_rounded_shape()
    {
        // Box [-1,1]³ with bevel 0.25: the inner box is [-0.75,0.75]³ and the surface is at distance 0.25 from it.
        var box = new BeveledBox(new Point3D(-1, -1, -1), new Point3D(1, 1, 1), 0.25);
        double F(Point3D p)
        {
            double dx = Math.Max(Math.Abs(p.x) - 0.75, 0), dy = Math.Max(Math.Abs(p.y) - 0.75, 0), dz = Math.Max(Math.Abs(p.z) - 0.75, 0);
            return Math.Sqrt(dx * dx + dy * dy + dz * dz) - 0.25;
        }

        var random = new SeededRandom(82);
        var sr = new ShadingRecord();
        for (int n = 0; n < 300; n++)
        {
            var ray = ImplicitSurfaceMarch.RandomRayTowards(random, 6, 1.5);
            if (F(ray.o) <= 0)
            {
                continue; // from outside only: inside, the hidden inner parts of the pieces are hit
            }

            double? expected = ImplicitSurfaceMarch.FirstRoot(F, ray, 20, 1e-3);
            bool hit = box.Hit(ray, out double t, sr);
            Assert.Equal(expected.HasValue, hit);
            if (hit)
            {
                Assert.Equal(expected!.Value, t, 6);
                Assert.True(sr.Normal.Dot(ray.d) < 0, "outward normals face rays from outside");
            }
        }
    }

    [Fact]
    public void Beveled_cylinder_top_and_rim()
    {
        var cyl = new BeveledCylinder(0, 2, 1, 0.2);
        Assert.True(cyl.Intersect(new Ray(new Point3D(0, 5, 0), new Vector3D(0, -1, 0)), out double t));
        Assert.Equal(3, t, 12);
        Assert.True(cyl.Intersect(new Ray(new Point3D(5, 1, 0), new Vector3D(-1, 0, 0)), out t));
        Assert.Equal(4, t, 12);
        // At the height of the bevel's centre circle the torus bulges to radius 1.
        Assert.True(cyl.Intersect(new Ray(new Point3D(5, 1.8, 0), new Vector3D(-1, 0, 0)), out t));
        Assert.Equal(4, t, 9);
        // The corner itself is rounded away.
        Assert.False(cyl.Intersect(new Ray(new Point3D(5, 1.995, 0.0), new Vector3D(-1, 0, 0)), out t) && t < 4.01);
    }
}
