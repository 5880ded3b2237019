using GMac.Core.Algebra;

namespace GMac.Core.Tests.Algebra;

/// <summary>
/// Right and left complements and the regressive product: metric independent, so they hold alike in
/// every signature, the degenerate projective one included.
/// </summary>
public class Complements_Identities
{
    // The sign of the permutation that sorts the indices of S followed by those of T, counted here by
    // bubble sort, independently of BasisBlade.OuterSign.
    private static int ConcatenationSign(int s, int t, int n)
    {
        var order = Enumerable.Range(0, n).Where(i => (s & (1 << i)) != 0)
            .Concat(Enumerable.Range(0, n).Where(i => (t & (1 << i)) != 0)).ToArray();
        var sign = 1;
        for (var i = 0; i < order.Length; i++)
        for (var j = 0; j + 1 < order.Length - i; j++)
            if (order[j] > order[j + 1])
            {
                (order[j], order[j + 1]) = (order[j + 1], order[j]);
                sign = -sign;
            }
        return sign;
    }

    [Theory]
    [MemberData(nameof(TestFrames.All), MemberType = typeof(TestFrames))]
    public void Basis_blade_wedge_its_right_complement_is_the_pseudoscalar_and_left_complement_wedge_it_too(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var all = frame.Pseudoscalar.Id;
        for (var id = 0; id < frame.BladeCount; id++)
        {
            var e = Multivector<double>.FromTerms(frame, [(new BasisBlade(id), 1.0)]);
            var right = e.RightComplement();
            var left = e.LeftComplement();
            Assert.Equal(ConcatenationSign(id, all & ~id, frame.Dimension), right[new BasisBlade(all & ~id)]);
            Assert.Equal(ConcatenationSign(all & ~id, id, frame.Dimension), left[new BasisBlade(all & ~id)]);
            Assert.Equal(1, right.TermCount);
            Assert.Equal(1, left.TermCount);
            Assert.Equal(1.0, e.Op(right)[frame.Pseudoscalar]);
            Assert.Equal(1.0, left.Op(e)[frame.Pseudoscalar]);
        }
    }

    [Theory]
    [MemberData(nameof(TestFrames.All), MemberType = typeof(TestFrames))]
    public void Left_complement_undoes_the_right_and_the_right_twice_is_minus_one_to_k_n_minus_k(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var n = frame.Dimension;
        var r = new RandomMultivectors(31);
        for (var i = 0; i < 10; i++)
        {
            var a = r.General(frame);
            MultivectorAssert.Close(a, a.RightComplement().LeftComplement());
            MultivectorAssert.Close(a, a.LeftComplement().RightComplement());
            var twice = a.MapTerms((b, c) => (b.Grade * (n - b.Grade)) % 2 == 0 ? c : -c);
            MultivectorAssert.Close(twice, a.RightComplement().RightComplement());
            MultivectorAssert.Close(twice, a.LeftComplement().LeftComplement());
        }
    }

    [Theory]
    [MemberData(nameof(TestFrames.All), MemberType = typeof(TestFrames))]
    public void Regressive_product_is_the_complement_of_the_outer_product_of_complements_either_way(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var r = new RandomMultivectors(32);
        for (var i = 0; i < 10; i++)
        {
            var (a, b) = (r.General(frame), r.General(frame));
            MultivectorAssert.Close(a.RightComplement().Op(b.RightComplement()).LeftComplement(), a.Regressive(b));
            // With the left complement first and the right one last the product is the same.
            MultivectorAssert.Close(a.LeftComplement().Op(b.LeftComplement()).RightComplement(), a.Regressive(b));
        }
    }

    [Theory]
    [MemberData(nameof(TestFrames.All), MemberType = typeof(TestFrames))]
    public void Regressive_product_of_blades_has_grade_r_plus_s_minus_n_and_the_pseudoscalar_is_its_unit(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var n = frame.Dimension;
        var r = new RandomMultivectors(33);
        var pseudoscalar = Multivector<double>.Pseudoscalar(frame);
        for (var ga = 0; ga <= n; ga++)
        for (var gb = 0; gb <= n; gb++)
        {
            var (a, b) = (r.Blade(frame, ga), r.Blade(frame, gb));
            var v = a.Regressive(b);
            Assert.All(v.Terms, t => Assert.Equal(ga + gb - n, t.Blade.Grade));
            if (ga + gb < n) Assert.True(v.IsZero);
            MultivectorAssert.Close(a, pseudoscalar.Regressive(a));
            MultivectorAssert.Close(a, a.Regressive(pseudoscalar));
        }
    }

    [Theory]
    [MemberData(nameof(TestFrames.All), MemberType = typeof(TestFrames))]
    public void Complementary_basis_blades_meet_in_the_sign_of_their_outer_product(string frameName)
    {
        // e_S ∨ e_T is the scalar σ when e_S ∧ e_T = σ I: the regressive product of complementary parts.
        var frame = TestFrames.ByName(frameName);
        var all = frame.Pseudoscalar.Id;
        for (var id = 0; id < frame.BladeCount; id++)
        {
            var (s, t) = (id, all & ~id);
            var es = Multivector<double>.FromTerms(frame, [(new BasisBlade(s), 1.0)]);
            var et = Multivector<double>.FromTerms(frame, [(new BasisBlade(t), 1.0)]);
            Assert.Equal((double)ConcatenationSign(s, t, frame.Dimension), es.Regressive(et).ScalarPart);
        }
    }

    [Theory]
    [MemberData(nameof(TestFrames.All), MemberType = typeof(TestFrames))]
    public void Regressive_product_is_associative_on_blades_and_general_multivectors(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var n = frame.Dimension;
        var r = new RandomMultivectors(34);
        for (var i = 0; i < 10; i++)
        {
            var (a, b, c) = (r.Blade(frame, n - 1), r.Blade(frame, n - 1), r.Blade(frame, 1 + i % (n - 1)));
            MultivectorAssert.Close(a.Regressive(b).Regressive(c), a.Regressive(b.Regressive(c)));
            var (x, y, z) = (r.General(frame), r.General(frame), r.General(frame));
            MultivectorAssert.Close(x.Regressive(y).Regressive(z), x.Regressive(y.Regressive(z)));
        }
    }

    [Theory]
    [InlineData("e2d")]
    [InlineData("e3d")]
    public void In_a_euclidean_frame_the_right_complement_is_the_reverse_times_the_pseudoscalar(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var r = new RandomMultivectors(35);
        var pseudoscalar = Multivector<double>.Pseudoscalar(frame);
        for (var i = 0; i < 10; i++)
        {
            var a = r.General(frame);
            MultivectorAssert.Close(a.Reverse().Gp(pseudoscalar), a.RightComplement());
        }
    }

    [Fact]
    public void Plane_and_point_complements_relabel_like_the_poincare_dual_of_klein()
    {
        // klein's documented example with basis order e0, e1, e2, e3: the plane e0 + 3e2 − 2e3 and
        // the point e123 + 3e013 − 2e021 = e123 + 3e013 + 2e012. The complement needs no metric.
        var frame = Frame.Euclidean("p", 4);
        static BasisBlade B(params int[] i) => new(i.Sum(k => 1 << k));
        var plane = Multivector<double>.FromTerms(frame, [(B(0), 1.0), (B(2), 3.0), (B(3), -2.0)]);
        var point = Multivector<double>.FromTerms(frame, [(B(1, 2, 3), 1.0), (B(0, 1, 3), 3.0), (B(0, 1, 2), 2.0)]);
        MultivectorAssert.Close(point, plane.RightComplement());
        MultivectorAssert.Close(plane, point.LeftComplement());
    }
}
