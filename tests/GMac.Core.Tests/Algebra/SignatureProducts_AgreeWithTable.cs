using GMac.Core.Algebra;

namespace GMac.Core.Tests.Algebra;

/// <summary>
/// Products in orthonormal frames are computed blade by blade without a table; they must agree
/// with the general table (Chevalley's recursion) that non-diagonal frames use.
/// </summary>
public sealed class SignatureProducts_AgreeWithTable
{
    [Theory]
    [InlineData(3, 0, 0)]
    [InlineData(2, 1, 1)]
    [InlineData(1, 3, 0)]
    public void Every_product_of_every_pair_of_blades_matches_the_table(int p, int q, int r)
    {
        var frame = Frame.FromSignature("s", p, q, r);
        foreach (var kind in Enum.GetValues<ProductKind>())
        for (var a = 0; a < frame.BladeCount; a++)
        for (var b = 0; b < frame.BladeCount; b++)
        {
            var expected = Multivector<double>.FromTerms(frame,
                frame.BladeProduct(kind, new BasisBlade(a), new BasisBlade(b)).Select(t => (new BasisBlade(t.Blade), t.Coefficient.ToDouble())));
            var actual = Multivector<double>.Basis(frame, new BasisBlade(a)).Product(kind, Multivector<double>.Basis(frame, new BasisBlade(b)));
            Assert.True(expected.Equals(actual), $"{kind} of {a} and {b}: expected {expected}, got {actual}");
        }
    }

    [Fact]
    public void Scalar_product_of_general_multivectors_matches_the_geometric_product_scalar_part()
    {
        var frame = Frame.FromSignature("s", 2, 2, 1);
        var random = new Random(5);
        Multivector<double> Random() => Multivector<double>.FromTerms(frame,
            Enumerable.Range(0, frame.BladeCount).Where(_ => random.Next(3) > 0).Select(id => (new BasisBlade(id), random.NextDouble() - 0.5)));
        for (var i = 0; i < 20; i++)
        {
            var (x, y) = (Random(), Random());
            Assert.Equal(x.Gp(y).ScalarPart, x.ScalarProduct(y), 12);
        }
    }

    [Fact]
    public void A_product_of_too_many_term_pairs_is_refused_with_the_sizes()
    {
        var frame = Frame.Euclidean("big", 12);
        var dense = Multivector<double>.FromTerms(frame, Enumerable.Range(0, frame.BladeCount).Select(id => (new BasisBlade(id), 1.0)));
        var e = Assert.Throws<AlgebraException>(() => dense.Gp(dense));
        Assert.True(e.ExceedsLimit);
        Assert.Contains("4096 terms", e.Message);
    }
}
