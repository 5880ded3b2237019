using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Transforms;

namespace RayTracer.Tests.Transforms;

public class AffineTransform_Inverse
{
    private static AffineTransform RandomTransform(SeededRandom random)
    {
        var t = AffineTransform.Identity;
        for (int k = 0; k < 5; k++)
        {
            t = random.NextInt(5) switch
            {
                0 => AffineTransform.Translation(random.NextDouble(-5, 5), random.NextDouble(-5, 5), random.NextDouble(-5, 5)),
                1 => AffineTransform.Scaling(random.NextDouble(0.2, 3), random.NextDouble(0.2, 3), random.NextDouble(0.2, 3)),
                2 => AffineTransform.RotationX(random.NextDouble(-3, 3)),
                3 => AffineTransform.RotationY(random.NextDouble(-3, 3)),
                _ => AffineTransform.Rotation(new Vector3D(random.NextDouble(-1, 1), random.NextDouble(-1, 1), 1), random.NextDouble(-3, 3)),
            } * t;
        }

        return t;
    }

    [Fact]
    public void Inverse_times_forward_is_identity()
    {
        var random = new SeededRandom(11);
        for (int n = 0; n < 200; n++)
        {
            var t = RandomTransform(random);
            var product = t.Inverse * t;
            for (int r = 0; r < 4; r++)
            {
                for (int c = 0; c < 4; c++)
                {
                    Assert.Equal(r == c ? 1.0 : 0.0, product[r, c], 9);
                }
            }
        }
    }

    [Fact]
    public void General_matrix_is_inverted_by_elimination_and_round_trips_points()
    {
        var random = new SeededRandom(12);
        for (int n = 0; n < 100; n++)
        {
            var m = new double[4, 4];
            for (int r = 0; r < 3; r++)
            {
                for (int c = 0; c < 4; c++)
                {
                    m[r, c] = random.NextDouble(-2, 2) + (r == c ? 3 : 0);
                }
            }

            m[3, 3] = 1;
            var t = AffineTransform.FromMatrix(m);
            var p = new Point3D(random.NextDouble(-9, 9), random.NextDouble(-9, 9), random.NextDouble(-9, 9));
            var back = t.InverseTransformPoint(t.TransformPoint(p));
            Assert.True(back.Distance(p) < 1e-9, $"{back} vs {p}");
        }
    }

    [Fact]
    public void Singular_matrix_is_rejected()
    {
        var m = new double[4, 4] { { 1, 2, 3, 0 }, { 2, 4, 6, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };
        Assert.Throws<ArgumentException>(() => AffineTransform.FromMatrix(m));
    }

    [Fact]
    public void Composition_applies_right_operand_first()
    {
        var t = AffineTransform.Translation(1, 0, 0) * AffineTransform.RotationZ(Math.PI / 2);
        var p = t.TransformPoint(new Point3D(1, 0, 0));
        // Rotate (1,0,0) to (0,1,0), then translate to (1,1,0).
        Assert.Equal(1, p.x, 12);
        Assert.Equal(1, p.y, 12);
        Assert.Equal(0, p.z, 12);
    }

    [Fact]
    public void Transformed_normals_stay_perpendicular_to_transformed_tangents()
    {
        var random = new SeededRandom(13);
        for (int n = 0; n < 200; n++)
        {
            var t = RandomTransform(random);
            var normal = new Normal3D(random.NextDouble(-1, 1), random.NextDouble(-1, 1), random.NextDouble(-1, 1));
            // A tangent: any vector perpendicular to the normal.
            var tangent = Vector3D.Cross(normal.ToVector(), new Vector3D(random.NextDouble(-1, 1), 1, random.NextDouble(-1, 1)));
            double dot = t.TransformNormal(normal).Normalized().Dot(t.TransformVector(tangent).Normalized());
            Assert.True(Math.Abs(dot) < 1e-9, $"dot = {dot}");
        }
    }

    [Fact]
    public void Rotations_preserve_lengths()
    {
        var random = new SeededRandom(14);
        for (int n = 0; n < 100; n++)
        {
            var axis = new Vector3D(random.NextDouble(-1, 1), random.NextDouble(-1, 1), random.NextDouble(-1, 1));
            var r = AffineTransform.Rotation(axis, random.NextDouble(-7, 7));
            var v = new Vector3D(random.NextDouble(-3, 3), random.NextDouble(-3, 3), random.NextDouble(-3, 3));
            Assert.Equal(v.Length, r.TransformVector(v).Length, 12);
            // Vectors along the axis are fixed.
            Assert.True((r.TransformVector(axis) - axis).Length < 1e-12);
        }
    }
}
