using GMac.Core.Algebra;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

/// <summary>
/// Expanding grows terms combinatorially: (a1 + … + a7)^16 has C(22, 6) = 74,613 terms and needs a
/// product of two 3,003-term halves, 9 million term products. Such a product is refused before it
/// starts, as too large, and one within the limits still expands exactly.
/// </summary>
public sealed class Scalar_SizeLimits
{
    private static Scalar SumOfSevenVariablesAndOne() =>
        Enumerable.Range(1, 6).Aggregate(Scalar.One, (s, i) => s + Scalar.Variable($"a{i}"));

    [Fact]
    public void A_power_whose_expansion_exceeds_the_limits_is_refused_as_too_large()
    {
        var e = Assert.Throws<AlgebraException>(() => Scalar.Pow(SumOfSevenVariablesAndOne(), 16));

        Assert.True(e.ExceedsLimit);
        Assert.Contains("3003 terms by 3003 terms", e.Message);
    }

    [Fact]
    public void A_sum_of_more_terms_than_the_limit_is_refused_as_too_large()
    {
        var half = Scalar.FromTerms(Enumerable.Range(0, Scalar.MaxTerms / 2 + 1).Select(i => new Term(1, Scalar.Variable($"x{i}").Terms[0].Monomial)));
        var other = Scalar.FromTerms(Enumerable.Range(0, Scalar.MaxTerms / 2 + 1).Select(i => new Term(1, Scalar.Variable($"y{i}").Terms[0].Monomial)));

        var e = Assert.Throws<AlgebraException>(() => half + other);

        Assert.True(e.ExceedsLimit);
    }

    [Fact]
    public void A_power_within_the_limits_expands_to_its_binomial_count_of_terms()
    {
        // (a1 + … + a6 + 1)^8: C(8 + 6, 6) = 3,003 monomials of degree at most 8 in six variables.
        Assert.Equal(3003, Scalar.Pow(SumOfSevenVariablesAndOne(), 8).Terms.Count);
    }
}
