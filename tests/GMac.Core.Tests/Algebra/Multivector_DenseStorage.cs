using GMac.Core.Algebra;
using GMac.Core.Numerics;

namespace GMac.Core.Tests.Algebra;

/// <summary>
/// The dense form of numeric multivectors in small frames: a product allocates its result only,
/// other value types than double work, and the paths for larger non-orthogonal frames agree with
/// the exact blade products.
/// </summary>
public class Multivector_DenseStorage
{
    [Theory]
    [InlineData("cga5d")]
    [InlineData("cl41")]
    [InlineData("skew")]
    public void A_product_allocates_only_its_result(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var r = new RandomMultivectors(21);
        var (a, b) = (r.General(frame), r.General(frame));
        for (var i = 0; i < 3; i++) _ = a.Gp(b); // tables built, code compiled

        var before = GC.GetAllocatedBytesForCurrentThread();
        var product = a.Gp(b);
        var allocated = GC.GetAllocatedBytesForCurrentThread() - before;

        // One coefficient array of 2^n doubles plus its header, and the multivector object.
        var resultSize = frame.BladeCount * sizeof(double) + 24 + 64;
        Assert.True(allocated <= resultSize, $"{allocated} bytes allocated for a product of {product.TermCount} terms, more than {resultSize}");
    }

    [Theory]
    [MemberData(nameof(TestFrames.All), MemberType = typeof(TestFrames))]
    public void Float_multivectors_agree_with_double_ones(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var r = new RandomMultivectors(22);
        var (a, b) = (r.General(frame), r.Vector(frame));
        var (fa, fb) = (a.Convert(c => (float)c), b.Convert(c => (float)c));
        foreach (var kind in Enum.GetValues<ProductKind>())
        {
            var expected = a.Product(kind, b);
            var actual = fa.Product(kind, fb).Convert(c => (double)c);
            for (var id = 0; id < frame.BladeCount; id++)
            {
                var blade = new BasisBlade(id);
                Assert.True(Math.Abs(expected[blade] - actual[blade]) < 1e-4, $"{kind}, {frame.BladeName(blade)}: {expected[blade]} vs {actual[blade]}");
            }
        }
        Assert.True(fa.Reverse().Reverse().Equals(fa));
        Assert.Equal(a.TermCount, fa.TermCount);
    }

    [Fact]
    public void Products_in_a_seven_dimensional_skew_frame_match_the_exact_blade_products()
    {
        // 128 blades: above the flat table, so entries are built pair by pair.
        var g = new Rational[7, 7];
        for (var i = 0; i < 7; i++)
        for (var j = 0; j < 7; j++)
            g[i, j] = i == j ? (i % 3 == 0 ? Rational.MinusOne : Rational.One + Rational.One) : Math.Abs(i - j) == 1 ? new Rational(1, 2) : Rational.Zero;
        var frame = new Frame("skew7", Enumerable.Range(1, 7).Select(i => $"e{i}").ToArray(), Metric.FromMatrix(g));
        var r = new RandomMultivectors(23);
        var (a, b) = (r.Blade(frame, 2), r.Vector(frame));
        foreach (var kind in new[] { ProductKind.Geometric, ProductKind.LeftContraction, ProductKind.Outer })
        {
            var expected = new double[frame.BladeCount];
            foreach (var (ba, ca) in a.Terms)
            foreach (var (bb, cb) in b.Terms)
            foreach (var term in frame.BladeProduct(kind, ba, bb))
                expected[term.Blade] += term.Coefficient.ToDouble() * ca * cb;
            var actual = a.Product(kind, b);
            for (var id = 0; id < frame.BladeCount; id++)
                Assert.True(Math.Abs(expected[id] - actual[new BasisBlade(id)]) < 1e-9, $"{kind}, blade {id}");
        }
    }

    [Fact]
    public void Zero_coefficients_are_not_terms()
    {
        var frame = TestFrames.Conformal;
        var v = Multivector<double>.Vector(frame, 1, 0, 2, 0, 0);
        Assert.Equal(2, v.TermCount);
        Assert.Equal([1], v.Grades);
        Assert.Equal(["no", "e2"], v.Terms.Select(t => frame.BladeName(t.Blade)));
        Assert.True(Multivector<double>.Zero(frame).IsZero);
        Assert.True(Multivector<double>.FromScalar(frame, 3).IsScalar);
        Assert.False(v.IsScalar);
        Assert.Equal("1 no + 2 e2", v.ToString());
    }
}
