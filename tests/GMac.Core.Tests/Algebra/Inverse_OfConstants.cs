using GMac.Core.Algebra;
using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Algebra;

/// <summary>A constant symbolic multivector that is no versor has no inverse of the form Ã/⟨AÃ⟩₀: known at generation, an error.</summary>
public class Inverse_OfConstants
{
    private static Multivector<Scalar> Constant(Frame f, params (string Blade, int Value)[] terms) =>
        terms.Aggregate(Multivector<Scalar>.Zero(f), (sum, t) => sum + Multivector<Scalar>.Basis(f, t.Blade) * Scalar.Constant(new Rational(t.Value, 1)));

    [Fact]
    public void One_plus_a_vector_is_no_versor_and_its_inverse_is_an_error()
    {
        var a = Constant(TestFrames.E3, ("1", 1), ("e1", 1));
        var e = Assert.Throws<AlgebraException>(() => a.Inverse());
        Assert.Contains("is not a versor or blade", e.Message);
    }

    [Fact]
    public void Constant_versors_and_blades_still_invert()
    {
        var f = TestFrames.E3;
        var v = Constant(f, ("e1", 1), ("e2", 2));
        var r = Constant(f, ("1", 3), ("e1^e2", 4));
        foreach (var m in new[] { v, r, Constant(f, ("e1^e2", 2)) })
        {
            var difference = m.Gp(m.Inverse()) - Multivector<Scalar>.FromScalar(f, Scalar.One);
            Assert.All(difference.Terms, t => Assert.True(Scalar.IsZero(t.Coefficient), $"{m}: {difference}"));
        }
    }

    [Fact]
    public void A_symbolic_non_versor_is_left_to_the_documented_formula()
    {
        // 1 + x for an input x: not known to be wrong for every value at generation, so no error.
        var f = TestFrames.E3;
        var a = Multivector<Scalar>.FromScalar(f, Scalar.One) + Multivector<Scalar>.Basis(f, "e1") * Scalar.Variable("x");
        var difference = a.Inverse() - a.Reverse() / a.QuasiNorm();
        Assert.All(difference.Terms, t => Assert.True(Scalar.IsZero(t.Coefficient)));
    }
}
