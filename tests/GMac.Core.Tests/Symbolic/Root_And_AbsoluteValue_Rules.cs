using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

/// <summary>
/// Rules on roots, absolute values and angles: each keeps the value (checked on random inputs of
/// both signs) and reaches the exact form it promises on a small case.
/// </summary>
public class Root_And_AbsoluteValue_Rules
{
    private static readonly Scalar A = Scalar.Variable("a"), B = Scalar.Variable("b"), C = Scalar.Variable("c"),
        D = Scalar.Variable("d"), X = Scalar.Variable("x"), Y = Scalar.Variable("y");

    private static void AssertSameValue(Scalar expected, Scalar actual)
    {
        var random = new Random(23);
        var variables = expected.Variables.Union(actual.Variables).ToArray();
        for (var i = 0; i < 30; i++)
        {
            var values = variables.ToDictionary(v => v, _ => random.NextDouble() * 4 - 2, StringComparer.Ordinal);
            var (e, a) = (expected.Evaluate(values), actual.Evaluate(values));
            Assert.True(Math.Abs(e - a) <= 1e-12 * Math.Max(1, Math.Abs(e)), $"{e} expected, {a} after the rule");
        }
    }

    [Fact]
    public void Square_root_of_an_expanded_square_is_the_absolute_value_of_the_root()
    {
        var root = A * C + B * D - 3 * X * Y;
        var square = root * root;

        var value = Scalar.Sqrt(square);

        Assert.Same(Scalar.Abs(root), value);
        Assert.Equal(1, value.Terms.Single().Monomial.Count);
        AssertSameValue(Scalar.Abs(root), value);
    }

    [Fact]
    public void Square_root_of_a_sum_of_squares_stays_a_root()
    {
        var sum = A * A + B * B + C * C;
        var almost = (A + B) * (A + B) + 1;

        Assert.Equal(AtomKind.Sqrt, Scalar.Sqrt(sum).Terms.Single().Monomial.Factors.Single().Atom.Kind);
        Assert.Equal(AtomKind.Sqrt, Scalar.Sqrt(almost).Terms.Single().Monomial.Factors.Single().Atom.Kind);
    }

    [Fact]
    public void Cosine_of_an_absolute_value_drops_it()
    {
        var u = A * X - B;
        var value = Scalar.Cos(3 * Scalar.Abs(u));

        Assert.Same(Scalar.Cos(3 * u), value);
        AssertSameValue(Scalar.Cos(3 * u), value);
    }

    [Fact]
    public void Atan2_moves_a_positive_denominator_of_its_first_argument_to_the_second()
    {
        var n = Scalar.Sqrt(A * A + B * B);
        var s = Scalar.Abs(C * D - X);

        var value = Scalar.Atan2(n / s, Scalar.One);

        Assert.Same(Scalar.Atan2(n, s), value);
        // checked against the library's atan of the quotient
        var random = new Random(5);
        for (var i = 0; i < 30; i++)
        {
            var values = new[] { "a", "b", "c", "d", "x" }.ToDictionary(v => v, _ => random.NextDouble() * 4 - 2, StringComparer.Ordinal);
            var expected = Math.Atan(n.Evaluate(values) / s.Evaluate(values));
            Assert.Equal(expected, value.Evaluate(values), 12);
        }
    }

    [Fact]
    public void Atan2_keeps_a_denominator_of_unknown_sign()
    {
        var value = Scalar.Atan2(A / (B + C), Scalar.One);

        Assert.Same(Scalar.One, value.Terms.Single().Monomial.Factors.Single().Atom.ArgumentArray[1]);
    }

    [Fact]
    public void Sine_of_an_absolute_value_over_that_value_is_the_signed_sine_over_its_argument()
    {
        // sin(φ)/φ · b with φ = |αΩ| and b = αΩ: the macro form of e^b for a bivector b
        var u = A * X;
        var phi = Scalar.Abs(u);
        var before = Scalar.Sin(phi) / phi * u * Y;

        var after = new RuleBasedCas().Simplify(before, Assumptions.None);

        Assert.Same(Scalar.Sin(u) * Y, after);
        AssertSameValue(before, after);
    }

    [Fact]
    public void Sine_of_an_absolute_value_alone_keeps_its_absolute_value()
    {
        var before = Scalar.Sin(Scalar.Abs(A * X)) * Y;

        var after = new RuleBasedCas().Simplify(before, Assumptions.None);

        Assert.Same(before, after);
    }
}
