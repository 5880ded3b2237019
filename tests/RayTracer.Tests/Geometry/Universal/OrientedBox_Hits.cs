using RayTracer.Bounds;
using RayTracer.Geometry;
using RayTracer.Geometry.Universal;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;
using RayTracer.Transforms;

namespace RayTracer.Tests.Geometry.Universal;

public class OrientedBox_Hits
{
    [Fact]
    public void Matches_a_rotated_instance_of_an_axis_aligned_box()
    {
        var rotation = AffineTransform.Rotation(new Vector3D(1, 1, 0.3), 0.9);
        var centre = new Point3D(2, -1, 3);
        var oriented = new OrientedBox(
            centre, rotation.TransformVector(Vector3D.UnitX), rotation.TransformVector(Vector3D.UnitY), new Vector3D(1.5, 0.5, 0.8));
        var instance = new Instance(new Box(new Point3D(-1.5, -0.5, -0.8), new Point3D(1.5, 0.5, 0.8)),
            AffineTransform.Translation(centre - Point3D.Origin) * rotation);
        var random = new SeededRandom(500);
        var a = new ShadingRecord();
        var b = new ShadingRecord();
        int hits = 0;
        for (int n = 0; n < 3000; n++)
        {
            var ray = ImplicitSurfaceMarch.RandomRayTowards(random, n % 3 == 0 ? 1 : 6, 2);
            ray.o += centre - Point3D.Origin;
            bool ho = oriented.Hit(ray, out double to, a);
            bool hi = instance.Hit(ray, out double ti, b);
            Assert.Equal(hi, ho);
            if (ho)
            {
                hits++;
                Assert.Equal(ti, to, 9);
                Assert.True((a.Normal - b.Normal).Length < 1e-9, $"{a.Normal} vs {b.Normal}");
            }
        }

        Assert.True(hits > 1000);
        BoundingBox box = oriented.GetBoundingBox(), reference = instance.GetBoundingBox();
        Assert.True(box.Min.Distance(reference.Min) < 1e-9 && box.Max.Distance(reference.Max) < 1e-9);
    }
}
