using GMac.Core.Algebra;

namespace GMac.Core.Tests.Algebra;

public class Products_Identities
{
    [Theory]
    [MemberData(nameof(TestFrames.All), MemberType = typeof(TestFrames))]
    public void Geometric_product_is_associative(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var r = new RandomMultivectors(1);
        for (var i = 0; i < 20; i++)
        {
            var (a, b, c) = (r.General(frame), r.General(frame), r.General(frame));
            MultivectorAssert.Close(a.Gp(b).Gp(c), a.Gp(b.Gp(c)));
        }
    }

    [Theory]
    [MemberData(nameof(TestFrames.All), MemberType = typeof(TestFrames))]
    public void Vector_product_is_contraction_plus_outer(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var r = new RandomMultivectors(2);
        for (var i = 0; i < 20; i++)
        {
            var (a, b) = (r.Vector(frame), r.Vector(frame));
            MultivectorAssert.Close(a.Gp(b), a.Lcp(b) + a.Op(b));
            // and the vector inner product is the metric's bilinear form
            var expected = 0.0;
            foreach (var (ba, ca) in a.Terms)
            foreach (var (bb, cb) in b.Terms)
                expected += ca * cb * frame.Metric[ba.BasisVectorIndices().Single(), bb.BasisVectorIndices().Single()].ToDouble();
            MultivectorAssert.Close(expected, a.Lcp(b).ScalarPart);
        }
    }

    /// <summary>
    /// Each product computed from its definition, grade part by grade part of the geometric product
    /// (Table 3-2), must equal the table-driven product.
    /// </summary>
    [Theory]
    [MemberData(nameof(TestFrames.All), MemberType = typeof(TestFrames))]
    public void Every_product_is_its_grade_selection_of_the_geometric_product(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var r = new RandomMultivectors(3);
        for (var i = 0; i < 5; i++)
        {
            var (a, b) = (r.General(frame), r.General(frame));
            foreach (var kind in Enum.GetValues<ProductKind>())
            {
                var expected = FromDefinition(kind, a, b);
                var actual = a.Product(kind, b);
                Assert.True((expected - actual).Terms.All(t => Math.Abs(t.Coefficient) < 1e-9), $"{kind}: expected {expected}, got {actual}");
            }
        }
    }

    private static Multivector<double> FromDefinition(ProductKind kind, Multivector<double> a, Multivector<double> b)
    {
        var frame = a.Frame;
        if (kind == ProductKind.Commutator) return (a.Gp(b) - b.Gp(a)) * 0.5;
        if (kind == ProductKind.AntiCommutator) return (a.Gp(b) + b.Gp(a)) * 0.5;
        var sum = Multivector<double>.Zero(frame);
        for (var ra = 0; ra <= frame.Dimension; ra++)
        for (var sb = 0; sb <= frame.Dimension; sb++)
        {
            var grade = kind switch
            {
                ProductKind.Geometric => int.MaxValue,
                ProductKind.Outer => ra + sb,
                ProductKind.LeftContraction => sb - ra,
                ProductKind.RightContraction => ra - sb,
                ProductKind.Scalar => 0,
                ProductKind.FatDot => Math.Abs(sb - ra),
                ProductKind.HestenesInner => ra == 0 || sb == 0 ? -1 : Math.Abs(sb - ra),
                _ => throw new InvalidOperationException(),
            };
            var gp = a.Grade(ra).Gp(b.Grade(sb));
            if (grade == int.MaxValue) sum += gp;
            else if (grade >= 0) sum += gp.Grade(grade);
        }
        return sum;
    }

    [Theory]
    [MemberData(nameof(TestFrames.All), MemberType = typeof(TestFrames))]
    public void Reverse_of_product_is_product_of_reverses_swapped(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var r = new RandomMultivectors(4);
        for (var i = 0; i < 20; i++)
        {
            var (a, b) = (r.General(frame), r.General(frame));
            MultivectorAssert.Close(a.Gp(b).Reverse(), b.Reverse().Gp(a.Reverse()));
            MultivectorAssert.Close(a.Gp(b).GradeInvolution(), a.GradeInvolution().Gp(b.GradeInvolution()));
            MultivectorAssert.Close(a.Gp(b).CliffordConjugate(), b.CliffordConjugate().Gp(a.CliffordConjugate()));
            MultivectorAssert.Close(a, a.Reverse().Reverse());
        }
    }

    [Theory]
    [MemberData(nameof(TestFrames.All), MemberType = typeof(TestFrames))]
    public void Outer_product_of_vectors_is_antisymmetric_and_metric_free(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var r = new RandomMultivectors(5);
        var (a, b) = (r.Vector(frame), r.Vector(frame));
        MultivectorAssert.Close(a.Op(b), -b.Op(a));
        Assert.True(a.Op(a).Terms.All(t => Math.Abs(t.Coefficient) < 1e-12));
        // metric-free: the same coefficients in a Euclidean frame of the same dimension
        var euclid = Frame.Euclidean("flat", frame.Dimension);
        var ea = Multivector<double>.FromTerms(euclid, a.Terms);
        var eb = Multivector<double>.FromTerms(euclid, b.Terms);
        MultivectorAssert.Close(Multivector<double>.FromTerms(frame, ea.Op(eb).Terms), a.Op(b));
    }

    [Fact]
    public void Worked_example_3_3_1_matches_the_thesis()
    {
        var f = Frame.Euclidean("e4d", 4);
        Multivector<double> M(string blade) => Multivector<double>.Basis(f, blade);
        var one = Multivector<double>.FromScalar(f, 1);
        var a = 5 * one + M("e1") - 3 * M("e1^e3");
        var b = 2 * M("e1^e4") + M("e2^e3^e4");

        var ab = 2 * M("e4") + 10 * M("e1^e4") + 6 * M("e3^e4") + 3 * M("e1^e2^e4") + 5 * M("e2^e3^e4") + M("e1^e2^e3^e4");
        var ba = -2 * M("e4") + 10 * M("e1^e4") - 6 * M("e3^e4") - 3 * M("e1^e2^e4") + 5 * M("e2^e3^e4") - M("e1^e2^e3^e4");
        Assert.True(ab.Equals(a.Gp(b)), $"AB = {a.Gp(b)}");
        Assert.True(ba.Equals(b.Gp(a)), $"BA = {b.Gp(a)}");
    }

    [Fact]
    public void Blade_names_carry_the_sign_of_their_order()
    {
        var f = TestFrames.E3;
        Assert.Equal(-1.0, Multivector<double>.Basis(f, "e2^e1")["e1^e2"]);
        Assert.Equal(1.0, Multivector<double>.Basis(f, "e3^e1^e2")["e1^e2^e3"]);
        Assert.Equal("e1^e3", f.BladeName(f.ParseBlade("e3^e1", out var sign)));
        Assert.Equal(-1, sign);
        Assert.False(f.TryParseBlade("e1^e1", out _, out _));
        Assert.False(f.TryParseBlade("e4", out _, out _));
    }

    [Fact]
    public void Degenerate_frame_null_vector_squares_to_zero()
    {
        var f = TestFrames.Projective;
        var e4 = Multivector<double>.Basis(f, "e4");
        Assert.True(e4.Gp(e4).IsZero);
        var e1 = Multivector<double>.Basis(f, "e1");
        MultivectorAssert.Close(-e1.Gp(e4), e4.Gp(e1));
    }

    [Fact]
    public void Many_basis_vectors_are_supported()
    {
        var f = Frame.FromSignature("big", 10, 2);
        var r = new RandomMultivectors(6);
        var (a, b, c) = (r.Versor(f, 2), r.Vector(f), r.Blade(f, 3));
        MultivectorAssert.Close(a.Gp(b).Gp(c), a.Gp(b.Gp(c)));
        MultivectorAssert.Close(Multivector<double>.FromScalar(f, 1), a.Gp(a.Inverse()));
        var big = Frame.Euclidean("e16", 16);
        var v = r.Vector(big);
        MultivectorAssert.Close(v.Gp(v).ScalarPart, v.Norm2());
    }
}
