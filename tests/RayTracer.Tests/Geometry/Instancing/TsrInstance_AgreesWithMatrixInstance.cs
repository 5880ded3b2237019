using RayTracer.Geometry;
using RayTracer.Geometry.Compound;
using RayTracer.Geometry.Generic;
using RayTracer.Geometry.Instancing;
using RayTracer.Geometry.Parametric;
using RayTracer.Geometry.Universal;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Transforms;
using Twister;
using static RayTracer.Tests.Geometry.Instancing.HitComparison;

namespace RayTracer.Tests.Geometry.Instancing;

public class TsrInstance_AgreesWithMatrixInstance
{
    public static TheoryData<string> Targets => ["sphere", "tube", "torus", "compound", "mesh"];

    [Theory]
    [MemberData(nameof(Targets))]
    public void Random_placements_hit_like_the_matrix_of_the_moved_frame(string name)
    {
        var random = new SeededRandom(1307);
        var totalHits = 0;
        for (var placement = 0; placement < 12; placement++)
        {
            var target = Target(name);
            var frame = RandomFrame(random, placement % 3 == 0 ? 1 : random.NextDouble(0.3, 3));
            var tsr = new TsrInstance(target, frame);
            var matrix = new Instance(target, MatrixOf(frame));
            var centre = new Point3D(frame.Origin.x, frame.Origin.y, frame.Origin.z);
            var scale = Length(frame.Vx);
            totalHits += AssertSameHits(matrix, tsr, RaysAround(random, centre, 6 * scale, 1.5 * scale, 150));
            // Rays from inside: origins next to the object's own origin, in the world.
            totalHits += AssertSameHits(matrix, tsr, RaysAround(random, centre, 0.3 * scale, 3 * scale, 100));
        }

        Assert.True(totalHits > 1000, $"only {totalHits} hits");
    }

    [Fact]
    public void A_frame_moved_by_twister_gives_the_expected_parts()
    {
        var axis = new Vector3D(1, 2, -2) / 3;
        var frame = FrameOfReference.Identity
            .Rotated(new TwistableVector(axis.x, axis.y, axis.z), 2.1)
            .Scaled(1.5)
            .Translated(new TwistableVector(4, -1, 0.5));
        var tsr = TsrTransform.FromFrame(frame);
        Assert.Equal(1.5, tsr.scale, 12);
        Assert.Equal(2.1, tsr.angle, 12);
        Assert.True((tsr.Axis - axis).Length < 1e-12, $"axis {tsr.Axis}");
        Assert.True((tsr.Translation - new Vector3D(4, -1, 0.5)).Length < 1e-12);
        var p = new Point3D(0.3, -0.7, 1.1);
        var expected = AffineTransform.Translation(4, -1, 0.5) * AffineTransform.Rotation(axis, 2.1) * AffineTransform.Scaling(1.5);
        Assert.True((tsr.ToWorld(p) - expected.TransformPoint(p)).Length < 1e-12);
        Assert.True((tsr.ToLocal(tsr.ToWorld(p)) - p).Length < 1e-12);
    }

    [Fact]
    public void A_frame_turned_half_way_round_is_read_as_a_half_turn()
    {
        // e1 onto −e1 has no unique shortest rotor; the analysis must still find the rotation.
        var frame = FrameOfReference.Identity.Rotated(new TwistableVector(0, 0, 1), Math.PI);
        var tsr = TsrTransform.FromFrame(frame);
        var p = new Point3D(1, 2, 3);
        Assert.True((tsr.ToWorld(p) - new Point3D(-1, -2, 3)).Length < 1e-12, $"{tsr.ToWorld(p)}");
        var upsideDown = FrameOfReference.Identity.Rotated(new TwistableVector(1, 0, 0), Math.PI);
        Assert.True((TsrTransform.FromFrame(upsideDown).ToWorld(p) - new Point3D(1, -2, -3)).Length < 1e-12);
    }

    private static GeometricObject Target(string name)
    {
        switch (name)
        {
            case "sphere":
                return new GenericSphere(1);
            case "tube":
                return new OpenCylinder(-1, 1.5, 0.8);
            case "torus":
                return new Torus(1, 0.35);
            case "mesh":
                // A smooth-shaded triangle mesh in its own hierarchy: a tessellated Twister torus.
                return new TessellatedSurface(TwistSurfaces.Torus(1, 0.4), 0.05);
            default:
                var compound = new CompoundObject();
                compound.Add(new Box(new Point3D(-1, -0.5, -0.5), new Point3D(0.5, 0.5, 0.8)));
                compound.Add(new Sphere(new Point3D(0.6, 0.4, 0), 0.6));
                return compound;
        }
    }

    /// <summary>The identity frame turned twice about random lines, scaled about a random centre and moved.</summary>
    private static FrameOfReference RandomFrame(SeededRandom random, double scale)
    {
        var a = RandomUnit(random);
        var b = RandomUnit(random);
        var through = RandomVector(random, 2);
        var centre = RandomVector(random, 2);
        var shift = RandomVector(random, 5);
        return FrameOfReference.Identity
            .Rotated(new TwistableVector(a.x, a.y, a.z), random.NextDouble(-Math.PI, Math.PI))
            .Rotated(new TwistableVector(b.x, b.y, b.z), random.NextDouble(-Math.PI, Math.PI), new TwistablePoint(through.x, through.y, through.z))
            .Scaled(scale, new TwistablePoint(centre.x, centre.y, centre.z))
            .Translated(new TwistableVector(shift.x, shift.y, shift.z));
    }

    /// <summary>The matrix whose columns are the moved frame: Vx, Vy, Vx × Vy / s and the origin.</summary>
    private static AffineTransform MatrixOf(FrameOfReference frame)
    {
        var x = new Vector3D(frame.Vx.x, frame.Vx.y, frame.Vx.z);
        var y = new Vector3D(frame.Vy.x, frame.Vy.y, frame.Vy.z);
        var z = Vector3D.Cross(x, y) / x.Length;
        var o = frame.Origin;
        return AffineTransform.FromMatrix(new double[,]
        {
            { x.x, y.x, z.x, o.x },
            { x.y, y.y, z.y, o.y },
            { x.z, y.z, z.z, o.z },
            { 0, 0, 0, 1 },
        });
    }

    private static double Length(TwistableVector v) => Math.Sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
}
