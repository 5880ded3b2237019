using GMac.Core.Algebra;
using GMac.Core.Numerics;

namespace GMac.Core.Tests.Algebra;

public class Versors_InverseDualExp
{
    [Theory]
    [MemberData(nameof(TestFrames.NonDegenerate), MemberType = typeof(TestFrames))]
    public void Versor_times_inverse_is_one(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var r = new RandomMultivectors(10);
        var one = Multivector<double>.FromScalar(frame, 1);
        for (var k = 1; k <= 4; k++)
        {
            var v = r.Versor(frame, k);
            MultivectorAssert.Close(one, v.Gp(v.Inverse()), 1e-8);
            MultivectorAssert.Close(one, v.Inverse().Gp(v), 1e-8);
        }
    }

    [Theory]
    [MemberData(nameof(TestFrames.NonDegenerate), MemberType = typeof(TestFrames))]
    public void Blade_times_inverse_is_one(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var r = new RandomMultivectors(11);
        var one = Multivector<double>.FromScalar(frame, 1);
        for (var k = 1; k <= frame.Dimension; k++)
        {
            var b = r.Blade(frame, k);
            if (Math.Abs(b.QuasiNorm()) < 1e-3) continue;
            MultivectorAssert.Close(one, b.Gp(b.Inverse()), 1e-8);
        }
    }

    [Theory]
    [MemberData(nameof(TestFrames.NonDegenerate), MemberType = typeof(TestFrames))]
    public void Dual_then_undual_is_identity(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var r = new RandomMultivectors(12);
        for (var i = 0; i < 10; i++)
        {
            var a = r.General(frame);
            MultivectorAssert.Close(a, a.Dual().Undual(), 1e-8);
            MultivectorAssert.Close(a, a.Undual().Dual(), 1e-8);
        }
        // dual with respect to a sub-blade: a vector lying in the blade comes back
        var blade = r.Blade(frame, 2);
        if (Math.Abs(blade.QuasiNorm()) > 1e-3)
        {
            var inside = r.Vector(frame).Lcp(blade);
            MultivectorAssert.Close(inside, inside.Dual(blade).Undual(blade), 1e-8);
        }
    }

    [Fact]
    public void Cross_product_is_the_dual_of_the_outer_product()
    {
        var f = TestFrames.E3;
        var r = new RandomMultivectors(13);
        var u = r.Vector(f);
        var v = r.Vector(f);
        var w = u.Op(v).Lcp(Multivector<double>.Pseudoscalar(f).Inverse());
        var (u1, u2, u3) = (u["e1"], u["e2"], u["e3"]);
        var (v1, v2, v3) = (v["e1"], v["e2"], v["e3"]);
        MultivectorAssert.Close(Multivector<double>.Vector(f, u2 * v3 - u3 * v2, u3 * v1 - u1 * v3, u1 * v2 - u2 * v1), w);
    }

    [Fact]
    public void Exp_of_euclidean_bivector_is_the_trig_rotor_and_matches_its_series()
    {
        var f = TestFrames.E3;
        var r = new RandomMultivectors(14);
        var b = r.OfGrade(f, 2) * 1.3;
        var exp = b.Exp();
        MultivectorAssert.Close(Series(b), exp, 1e-10);
        MultivectorAssert.Close(Multivector<double>.FromScalar(f, 1), exp.Gp(exp.Reverse()), 1e-10);

        var theta = 0.7;
        var rotor = (Multivector<double>.Basis(f, "e1^e2") * (-theta / 2)).Exp();
        MultivectorAssert.Close(Multivector<double>.FromScalar(f, Math.Cos(theta / 2)) - Multivector<double>.Basis(f, "e1^e2") * Math.Sin(theta / 2), rotor);
    }

    [Fact]
    public void Exp_of_boost_and_null_bivector_uses_hyperbolic_and_linear_forms()
    {
        var f = TestFrames.Cl41;
        var boost = Multivector<double>.Basis(f, "e1^e5") * 0.8; // squares to +0.64
        MultivectorAssert.Close(Series(boost), boost.Exp(), 1e-10);

        var c = TestFrames.Conformal;
        var translator = Multivector<double>.Vector(c, 0, 0.3, -1.2, 2, 0).Op(Multivector<double>.Basis(c, "ni")) * -0.5;
        MultivectorAssert.Close(Multivector<double>.FromScalar(c, 1) + translator, translator.Exp());
    }

    private static Multivector<double> Series(Multivector<double> b)
    {
        var sum = Multivector<double>.FromScalar(b.Frame, 1);
        var term = Multivector<double>.FromScalar(b.Frame, 1);
        for (var k = 1; k < 40; k++)
        {
            term = term.Gp(b) * (1.0 / k);
            sum += term;
        }
        return sum;
    }

    [Fact]
    public void Norms_follow_their_definitions()
    {
        var f = TestFrames.E3;
        var r = new RandomMultivectors(15);
        var a = r.General(f);
        var sumOfSquares = a.Terms.Sum(t => t.Coefficient * t.Coefficient);
        MultivectorAssert.Close(sumOfSquares, a.Norm2());
        MultivectorAssert.Close(Math.Sqrt(sumOfSquares), a.Norm());
        MultivectorAssert.Close(a.Gp(a.Reverse()).ScalarPart, a.QuasiNorm());

        // Minkowski: the quasi-norm of e5 is −1, the norm is 1
        var e5 = Multivector<double>.Basis(TestFrames.Cl41, "e5");
        Assert.Equal(-1.0, e5.QuasiNorm());
        Assert.Equal(1.0, e5.Norm());
    }

    [Fact]
    public void Outermorphism_preserves_outer_product_and_scales_pseudoscalar_by_determinant()
    {
        var f = TestFrames.E3;
        var r = new RandomMultivectors(16);
        var m = new double[3, 3];
        for (var i = 0; i < 3; i++)
        for (var j = 0; j < 3; j++)
            m[i, j] = r.Number();
        var map = new Outermorphism<double>(f, f, m);
        var (a, b, c) = (r.Vector(f), r.Vector(f), r.Vector(f));
        MultivectorAssert.Close(map.Apply(a).Op(map.Apply(b)).Op(map.Apply(c)), map.Apply(a.Op(b).Op(c)));
        var det = m[0, 0] * (m[1, 1] * m[2, 2] - m[1, 2] * m[2, 1]) - m[0, 1] * (m[1, 0] * m[2, 2] - m[1, 2] * m[2, 0]) + m[0, 2] * (m[1, 0] * m[2, 1] - m[1, 1] * m[2, 0]);
        MultivectorAssert.Close(Multivector<double>.Pseudoscalar(f) * det, map.Apply(Multivector<double>.Pseudoscalar(f)));
    }
}
