using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

public class Scalar_NumericAgreement
{
    [Fact]
    public void Symbolic_then_numeric_equals_numeric_on_random_trees()
    {
        var trees = new RandomExpressionTrees(seed: 20261121);
        for (var n = 0; n < 300; n++)
        {
            var (symbolic, direct) = trees.Next(depth: 4);
            for (var k = 0; k < 4; k++)
            {
                var point = trees.Point();
                var expected = direct(point);
                var actual = symbolic.Evaluate(RandomExpressionTrees.Lookup(point));
                // Relative error; below magnitude 1 it is measured absolutely, because a function near a
                // zero (cos close to pi/2) turns last-bit differences of its argument into large relative ones.
                var error = Math.Abs(actual - expected) / Math.Max(1, Math.Abs(expected));
                Assert.True(error <= 1e-12, $"{symbolic} at ({string.Join(", ", point)}): {actual} vs {expected}");
            }
        }
    }

    [Fact]
    public void Substitution_then_evaluation_equals_evaluation_at_the_substituted_values()
    {
        var trees = new RandomExpressionTrees(seed: 7);
        var x1 = Scalar.Variable("x1");
        var x2 = Scalar.Variable("x2");
        for (var n = 0; n < 100; n++)
        {
            var (symbolic, direct) = trees.Next(depth: 3);
            // x0 := x1 * x2 + 1/2
            var substituted = symbolic.Substitute("x0", x1 * x2 + Scalar.Constant(new GMac.Core.Numerics.Rational(1, 2)));
            Assert.DoesNotContain("x0", substituted.Variables);
            var point = trees.Point();
            var moved = new[] { point[1] * point[2] + 0.5, point[1], point[2] };
            var expected = direct(moved);
            var actual = substituted.Evaluate(RandomExpressionTrees.Lookup(point));
            Assert.True(Math.Abs(actual - expected) <= 1e-12 * Math.Max(1, Math.Abs(expected)), $"{substituted}: {actual} vs {expected}");
        }
    }

    [Fact]
    public void Missing_variable_values_are_reported_by_name()
    {
        var error = Assert.Throws<KeyNotFoundException>(() => Scalar.Variable("speed").Evaluate(new Dictionary<string, double>()));
        Assert.Contains("speed", error.Message);
    }
}
