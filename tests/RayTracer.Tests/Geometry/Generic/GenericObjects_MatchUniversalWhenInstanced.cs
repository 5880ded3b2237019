using RayTracer.Geometry;
using RayTracer.Geometry.Generic;
using RayTracer.Geometry.Universal;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;
using RayTracer.Transforms;

namespace RayTracer.Tests.Geometry.Generic;

/// <summary>A generic object placed by an instance and the universal object built at the same place agree.</summary>
public class GenericObjects_MatchUniversalWhenInstanced
{
    private static readonly AffineTransform Placement =
        AffineTransform.Translation(1, -2, 0.5) * AffineTransform.Rotation(new Vector3D(1, 2, -1), 0.8) * AffineTransform.Scaling(1.7);

    public static TheoryData<string> Cases => ["sphere", "plane", "disk", "rectangle"];

    private static (GeometricObject Generic, GeometricObject Universal) Make(string name)
    {
        var centre = Placement.TransformPoint(Point3D.Origin);
        var up = Placement.TransformNormal(new Normal3D(0, 1, 0)).Normalized();
        return name switch
        {
            "sphere" => (new GenericSphere(1.5), new Sphere(centre, 1.5 * 1.7)),
            "plane" => (new GenericPlane(), new Plane(centre, up)),
            "disk" => (new GenericDisk(2), new Disk(centre, up, 2 * 1.7)),
            _ => (new GenericRectangle(1, 0.5), new Rectangle(
                Placement.TransformPoint(new Point3D(-1, 0, -0.5)),
                Placement.TransformVector(new Vector3D(2, 0, 0)),
                Placement.TransformVector(new Vector3D(0, 0, 1)),
                up)),
        };
    }

    [Theory]
    [MemberData(nameof(Cases))]
    public void Hits_distances_and_normals_agree(string name)
    {
        var (generic, universal) = Make(name);
        var instance = new Instance(generic, Placement);
        var random = new SeededRandom(400 + (ulong)name.Length);
        var a = new ShadingRecord();
        var b = new ShadingRecord();
        int hits = 0;
        for (int n = 0; n < 2000; n++)
        {
            var ray = ImplicitSurfaceMarch.RandomRayTowards(random, 8, 3);
            ray.o += Placement.TransformPoint(Point3D.Origin) - Point3D.Origin;
            bool hi = instance.Hit(ray, out double ti, a);
            bool hu = universal.Hit(ray, out double tu, b);
            if (hi != hu)
            {
                // Only rays that graze an edge within rounding may disagree.
                var p = ray.At(hi ? ti : tu);
                Assert.Fail($"{name}: instance {hi}, universal {hu} at {p}");
            }

            if (hi)
            {
                hits++;
                Assert.True(Math.Abs(ti - tu) <= 1e-9 * Math.Max(1, tu), $"{name}: t {ti} vs {tu}");
                Assert.True((a.Normal - b.Normal).Length < 1e-9, $"{name}: {a.Normal} vs {b.Normal}");
            }
        }

        Assert.True(hits > 100, $"{name}: {hits} hits");
    }
}
