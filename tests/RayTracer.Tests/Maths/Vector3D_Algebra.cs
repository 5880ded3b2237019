using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Randomness;

namespace RayTracer.Tests.Maths;

public class Vector3D_Algebra
{
    [Fact]
    public void Cross_product_is_perpendicular_and_satisfies_lagranges_identity()
    {
        var random = new SeededRandom(31);
        for (int n = 0; n < 500; n++)
        {
            var a = new Vector3D(random.NextDouble(-5, 5), random.NextDouble(-5, 5), random.NextDouble(-5, 5));
            var b = new Vector3D(random.NextDouble(-5, 5), random.NextDouble(-5, 5), random.NextDouble(-5, 5));
            var c = Vector3D.Cross(a, b);
            Assert.Equal(0, Vector3D.Dot(c, a), 9);
            Assert.Equal(0, Vector3D.Dot(c, b), 9);
            double lhs = c.LengthSquared + Math.Pow(Vector3D.Dot(a, b), 2);
            Assert.Equal(a.LengthSquared * b.LengthSquared, lhs, 7);
        }
    }

    [Fact]
    public void Normalized_has_unit_length_and_same_direction()
    {
        var v = new Vector3D(3, -4, 12);
        var u = v.Normalized();
        Assert.Equal(1, u.Length, 15);
        Assert.Equal(3.0 / 13, u.x, 15);
        Assert.Equal(-4.0 / 13, u.y, 15);
    }

    [Fact]
    public void Point_minus_point_is_the_vector_between_them()
    {
        var p = new Point3D(1, 2, 3);
        var q = new Point3D(4, 6, 3);
        Assert.Equal(new Vector3D(3, 4, 0), q - p);
        Assert.Equal(q, p + (q - p));
        Assert.Equal(5, p.Distance(q), 15);
    }

    [Fact]
    public void Color_power_and_arithmetic()
    {
        var c = new RGBColor(0.25, 1, 4);
        Assert.Equal(new RGBColor(0.5, 1, 2), c.Pow(0.5));
        Assert.Equal(new RGBColor(0.5, 2, 8), c * 2);
        Assert.Equal(new RGBColor(0.0625, 1, 16), c * c);
        Assert.Equal(4, c.MaxComponent);
    }

    [Fact]
    public void Orthonormal_basis_is_orthonormal_and_right_handed()
    {
        var random = new SeededRandom(32);
        for (int n = 0; n < 200; n++)
        {
            var w = new Vector3D(random.NextDouble(-1, 1), random.NextDouble(-1, 1), random.NextDouble(-1, 1));
            var f = OrthonormalBasis.FromW(w);
            Assert.Equal(1, f.U.Length, 12);
            Assert.Equal(1, f.V.Length, 12);
            Assert.Equal(0, Vector3D.Dot(f.U, f.V), 12);
            Assert.Equal(0, Vector3D.Dot(f.U, f.W), 12);
            Assert.True((Vector3D.Cross(f.U, f.V) - f.W).Length < 1e-12);
        }
    }
}
