using RayTracer.Geometry;
using RayTracer.Geometry.Generic;
using RayTracer.Geometry.Instancing;
using RayTracer.Geometry.Universal;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Transforms;
using static RayTracer.Tests.Geometry.Instancing.HitComparison;

namespace RayTracer.Tests.Geometry.Instancing;

public class RstrInstance_AgreesWithMatrixInstance
{
    public static TheoryData<string> Targets => ["sphere", "tube", "cone", "torus", "disk"];

    [Theory]
    [MemberData(nameof(Targets))]
    public void Random_placements_hit_like_the_rotation_onto_the_direction(string name)
    {
        var random = new SeededRandom(2203);
        var totalHits = 0;
        // Random directions, and the two that the mirror treats apart: along e2 and against it.
        var directions = Enumerable.Range(0, 10).Select(_ => RandomUnit(random)).Append(Vector3D.UnitY).Append(-Vector3D.UnitY)
            .Append(new Vector3D(1e-9, 1, 0)).ToList();
        foreach (var direction in directions)
        {
            var target = Target(name);
            var position = new Point3D(0, 0, 0) + RandomVector(random, 5);
            var rstr = new RstrInstance(target, position, direction * random.NextDouble(0.2, 4));
            var matrix = new Instance(target, AffineTransform.Translation((Vector3D)position) * TurningYOnto(direction));
            totalHits += AssertSameHits(matrix, rstr, RaysAround(random, position, 6, 1.5, 150));
            totalHits += AssertSameHits(matrix, rstr, RaysAround(random, position + 0.4 * direction, 0.2, 3, 100));
            Assert.True((rstr.Direction - direction.Normalized()).Length < 1e-12, $"{rstr.Direction} vs {direction}");
        }

        Assert.True(totalHits > 800, $"only {totalHits} hits");
    }

    [Fact]
    public void Universal_cylinder_with_rstr_folded_in_hits_like_the_universal_cylinder()
    {
        var random = new SeededRandom(77);
        var hits = 0;
        for (var k = 0; k < 20; k++)
        {
            var start = new Point3D(0, 0, 0) + RandomVector(random, 4);
            var axis = RandomUnit(random) * random.NextDouble(0.5, 3);
            var radius = random.NextDouble(0.1, 1);
            var reference = new Cylinder(start, axis, radius);
            var folded = new GaUniversalCylinder(start, axis, radius);
            hits += AssertSameHits(reference, folded, RaysAround(random, start + 0.5 * axis, 5, 1.5, 150));
            hits += AssertSameHits(reference, folded, RaysAround(random, start + 0.5 * axis, 0.05, 3, 50));
            var box = reference.GetBoundingBox();
            var ours = folded.GetBoundingBox();
            Assert.True((box.Min - ours.Min).Length < 1e-12 && (box.Max - ours.Max).Length < 1e-12);
        }

        Assert.True(hits > 1000, $"only {hits} hits");
    }

    private static GeometricObject Target(string name) => name switch
    {
        "sphere" => new GenericSphere(0.9),
        "tube" => new OpenCylinder(0, 1.8, 0.7),
        "cone" => new Cone(1.5, 0.8),
        "torus" => new Torus(1, 0.3),
        _ => new GenericDisk(1.2),
    };

    /// <summary>A rotation taking e2 onto the unit direction, from an orthonormal frame built by hand.</summary>
    private static AffineTransform TurningYOnto(Vector3D direction)
    {
        var y = direction.Normalized();
        var helper = Math.Abs(y.x) < 0.9 ? Vector3D.UnitX : Vector3D.UnitZ;
        var x = Vector3D.Cross(y, helper).Normalized();
        var z = Vector3D.Cross(x, y);
        return AffineTransform.FromMatrix(new double[,]
        {
            { x.x, y.x, z.x, 0 },
            { x.y, y.y, z.y, 0 },
            { x.z, y.z, z.z, 0 },
            { 0, 0, 0, 1 },
        });
    }
}
