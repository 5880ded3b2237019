using GMac.Core.Algebra;
using GMac.Core.Numerics;

namespace GMac.Core.Tests.Algebra;

public class Algebra_BadInput
{
    [Fact]
    public void Non_symmetric_matrix_names_frame_and_entries()
    {
        var ex = Assert.Throws<AlgebraException>(() => Metric.FromMatrix(new Rational[,] { { 1, 2 }, { 3, 1 } }, "bent"));
        Assert.Contains("'bent'", ex.Message);
        Assert.Contains("(1,2) is 2", ex.Message);
        Assert.Contains("(2,1) is 3", ex.Message);
    }

    [Fact]
    public void Non_square_matrix_is_rejected()
    {
        var ex = Assert.Throws<AlgebraException>(() => Metric.FromMatrix(new Rational[,] { { 1, 0, 0 }, { 0, 1, 0 } }, "flat"));
        Assert.Contains("2x3", ex.Message);
    }

    [Fact]
    public void Too_many_basis_vectors_are_rejected()
    {
        var ex = Assert.Throws<AlgebraException>(() => Frame.Euclidean("huge", Frame.MaxDimension + 1));
        Assert.Contains("'huge'", ex.Message);
        Assert.Contains($"{Frame.MaxDimension + 1} basis vectors", ex.Message);
    }

    [Fact]
    public void Wrong_number_of_names_and_duplicate_names_are_rejected()
    {
        Assert.Contains("3 basis vector names", Assert.Throws<AlgebraException>(() => new Frame("f", ["a", "b", "c"], Metric.Euclidean(2))).Message);
        Assert.Contains("'a' is used twice", Assert.Throws<AlgebraException>(() => new Frame("f", ["a", "a"], Metric.Euclidean(2))).Message);
    }

    [Fact]
    public void Inverse_of_null_versor_throws()
    {
        var cga = TestFrames.Conformal;
        var ni = Multivector<double>.Basis(cga, "ni");
        var ex = Assert.Throws<AlgebraException>(() => ni.Inverse());
        Assert.Contains("'cga5d'", ex.Message);
        Assert.Contains("null", ex.Message);
    }

    [Fact]
    public void Mixing_frames_throws()
    {
        var a = Multivector<double>.Basis(TestFrames.E3, "e1");
        var b = Multivector<double>.Basis(TestFrames.E2, "e1");
        var ex = Assert.Throws<AlgebraException>(() => a.Gp(b));
        Assert.Contains("'e3d'", ex.Message);
        Assert.Contains("'e2d'", ex.Message);
        Assert.Throws<AlgebraException>(() => a + b);
    }

    [Fact]
    public void Dual_in_degenerate_frame_throws()
    {
        var e1 = Multivector<double>.Basis(TestFrames.Projective, "e1");
        Assert.Contains("'pga'", Assert.Throws<AlgebraException>(() => e1.Dual()).Message);
    }

    [Fact]
    public void Unknown_blade_names_the_frame_basis()
    {
        var ex = Assert.Throws<AlgebraException>(() => Multivector<double>.Basis(TestFrames.E3, "e1^x"));
        Assert.Contains("e1, e2, e3", ex.Message);
    }
}
