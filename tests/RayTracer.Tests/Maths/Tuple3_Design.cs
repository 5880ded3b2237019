using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Transforms;

namespace RayTracer.Tests.Maths;

public class Tuple3_Design
{
    /// <summary>Laws every three-component value obeys, checked once for all four types.</summary>
    private static void SharedLaws<T>() where T : struct, ITuple3<T>
    {
        var random = new SeededRandom(7);
        for (var n = 0; n < 100; n++)
        {
            var a = T.Create(random.NextDouble(-5, 5), random.NextDouble(-5, 5), random.NextDouble(-5, 5));
            var same = T.Create(a.Components.First, a.Components.Second, a.Components.Third);
            Assert.True(a == same);
            Assert.Equal(a.GetHashCode(), same.GetHashCode());
            var doubled = a * 2.0;
            Assert.Equal(2 * a.Components.First, doubled.Components.First);
            Assert.Equal(2 * a.Components.Third, doubled.Components.Third);
            Assert.True(doubled != a || a.Components == (0, 0, 0));
        }
    }

    [Fact]
    public void Points_vectors_normals_and_colours_share_equality_hashing_and_scaling()
    {
        SharedLaws<Point3D>();
        SharedLaws<Vector3D>();
        SharedLaws<Normal3D>();
        SharedLaws<RGBColor>();
    }

    [Fact]
    public void Point_algebra_is_affine_point_minus_point_is_a_vector_point_plus_vector_a_point()
    {
        Assert.Equal(typeof(Vector3D), typeof(Point3D).GetMethod("op_Subtraction", [typeof(Point3D), typeof(Point3D)])!.ReturnType);
        Assert.Equal(typeof(Point3D), typeof(Point3D).GetMethod("op_Addition", [typeof(Point3D), typeof(Vector3D)])!.ReturnType);
        Assert.Null(typeof(Point3D).GetMethod("op_Addition", [typeof(Point3D), typeof(Point3D)]));
        var p = new Point3D(1, 2, 3);
        var q = new Point3D(4, 6, 3);
        Assert.Equal(5.0, (q - p).Length, 15);
        Assert.Equal(q, p + (q - p));
    }

    [Fact]
    public void Normals_follow_the_inverse_transpose_and_stay_perpendicular_to_the_surface()
    {
        // A shear tilts a plane; the matrix itself would tilt its normal off the plane, the inverse transpose does not.
        var shear = AffineTransform.FromMatrix(new double[,] { { 1, 2, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } });
        var n = new Normal3D(0, 1, 0); // the plane y = 0 spanned by x and z
        var tangent = shear.TransformVector(new Vector3D(1, 0, 0));
        var other = shear.TransformVector(new Vector3D(0, 0, 1));
        var mapped = shear.TransformNormal(n);
        Assert.Equal(0.0, mapped.Dot(tangent), 15);
        Assert.Equal(0.0, mapped.Dot(other), 15);
        var asVector = shear.TransformVector((Vector3D)n);
        Assert.Equal(2.0, asVector.Dot(tangent), 15);
    }
}
