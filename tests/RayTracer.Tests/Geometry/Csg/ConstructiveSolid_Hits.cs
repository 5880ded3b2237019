using RayTracer.Geometry;
using RayTracer.Geometry.Csg;
using RayTracer.Geometry.Generic;
using RayTracer.Geometry.Universal;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Geometry.Csg;

public class ConstructiveSolid_Hits
{
    private static readonly Point3D CenterA = new(0, 0, 0);
    private static readonly Point3D CenterB = new(0.9, 0.3, 0);

    private static double Ball(Point3D p, Point3D c, double r) => p.Distance(c) - r;

    public static TheoryData<SolidOperation> Operations => [SolidOperation.Union, SolidOperation.Intersection, SolidOperation.Difference];

    [Theory]
    [MemberData(nameof(Operations))]
    public void Sphere_combinations_match_the_marched_signed_distance(SolidOperation operation)
    {
        var solid = new ConstructiveSolid(operation, new Sphere(CenterA, 1), new Sphere(CenterB, 0.8));
        Func<Point3D, double> f = operation switch
        {
            SolidOperation.Union => p => Math.Min(Ball(p, CenterA, 1), Ball(p, CenterB, 0.8)),
            SolidOperation.Intersection => p => Math.Max(Ball(p, CenterA, 1), Ball(p, CenterB, 0.8)),
            _ => p => Math.Max(Ball(p, CenterA, 1), -Ball(p, CenterB, 0.8)),
        };
        var random = new SeededRandom(300 + (ulong)operation);
        var sr = new ShadingRecord();
        int hits = 0;
        for (int n = 0; n < 400; n++)
        {
            // Rays from inside and outside, with unnormalized directions.
            var ray = ImplicitSurfaceMarch.RandomRayTowards(random, n % 2 == 0 ? 1.2 : 5, 1.2);
            ray.d *= random.NextDouble(0.3, 3);
            double? expected = ImplicitSurfaceMarch.FirstRoot(f, new Ray(ray.o, ray.d.Normalized()), 15, 1e-3);
            bool hit = solid.Hit(ray, out double t, sr);
            Assert.True(expected.HasValue == hit, $"{operation}: ray {ray} expected {expected}, got {(hit ? t : "miss")}");
            if (!hit)
            {
                continue;
            }

            hits++;
            Assert.Equal(expected!.Value, t * ray.d.Length, 6);
            var p = ray.At(t);
            // The normal points out of the combined solid: stepping along it leaves the solid.
            Assert.True(f(p + 1e-4 * sr.Normal.ToVector()) > 0 && f(p - 1e-4 * sr.Normal.ToVector()) < 0, $"{operation}: normal {sr.Normal} at {p}");
        }

        Assert.True(hits > 50, $"{operation}: {hits} hits");
    }

    [Fact]
    public void Box_with_a_spherical_bite_and_nested_operands()
    {
        // (box − sphere) ∪ raised torus, with instanced operands: any closed solid can be an operand.
        GeometricObject box = new Instance(new Box(new Point3D(-1, -1, -1), new Point3D(1, 1, 1))).Translate(0, 0, 0);
        var bitten = new ConstructiveSolid(SolidOperation.Difference, box, new Sphere(new Point3D(0, 0, 1), 0.6));
        var solid = new ConstructiveSolid(SolidOperation.Union, bitten, new Instance(new Torus(2, 0.25)).Translate(0, 3, 0));
        // Straight down the z axis into the bite: the bottom of the spherical dent at z = 0.4.
        Assert.True(solid.Intersect(new Ray(new Point3D(0, 0, 5), new Vector3D(0, 0, -1)), out double t));
        Assert.Equal(4.6, t, 9);
        // Beside the bite the box face at z = 1 is hit.
        Assert.True(solid.Intersect(new Ray(new Point3D(0.8, 0.8, 5), new Vector3D(0, 0, -1)), out t));
        Assert.Equal(4, t, 9);
        // The torus ring (radius 2 around the y axis, at height 3) is part of the union.
        Assert.True(solid.Intersect(new Ray(new Point3D(2, 8, 0), new Vector3D(0, -1, 0)), out t));
        Assert.Equal(4.75, t, 9);
    }

    [Fact]
    public void Disjoint_intersection_is_empty()
    {
        var solid = new ConstructiveSolid(SolidOperation.Intersection, new Sphere(new Point3D(-3, 0, 0), 1), new Sphere(new Point3D(3, 0, 0), 1));
        Assert.False(solid.Intersect(new Ray(new Point3D(-10, 0, 0), new Vector3D(1, 0, 0)), out _));
        Assert.True(solid.GetBoundingBox().IsEmpty);
    }
}
