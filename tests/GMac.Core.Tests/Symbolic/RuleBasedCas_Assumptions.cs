using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

public class RuleBasedCas_Assumptions
{
    private static readonly Scalar X = Scalar.Variable("x");
    private static readonly Scalar Y = Scalar.Variable("y");
    private readonly RuleBasedCas _cas = new();

    [Fact]
    public void Square_root_of_a_square_is_the_variable_only_when_it_is_non_negative()
    {
        var root = Scalar.Sqrt(X * X);
        Assert.Same(X, _cas.Simplify(root, Assumptions.None.WithMinimum("x", 0)));
        Assert.Same(Scalar.Abs(X), _cas.Simplify(root, Assumptions.None));
        Assert.Same(-X, _cas.Simplify(root, Assumptions.None.WithMaximum("x", -1)));
        Assert.Same(Scalar.Abs(X), _cas.Simplify(root, Assumptions.None.WithBounds("x", -1, 1)));
    }

    [Fact]
    public void Absolute_value_follows_the_sign_found_by_interval_arithmetic()
    {
        var negative = Assumptions.None.WithMaximum("x", new Rational(-1, 10)).WithBounds("y", 2, 3);
        Assert.Same(-X, _cas.Simplify(Scalar.Abs(X), negative));
        // x*y < 0 and y - x > 0 under these bounds.
        Assert.Same(-(X * Y), _cas.Simplify(Scalar.Abs(X * Y), negative));
        Assert.Same(Y - X, _cas.Simplify(Scalar.Abs(Y - X), negative));
        // exp is positive whatever its argument.
        Assert.Same(Scalar.Exp(X), _cas.Simplify(Scalar.Abs(Scalar.Exp(X)), Assumptions.None));
        // Unknown sign: unchanged.
        Assert.Same(Scalar.Abs(X + Y), _cas.Simplify(Scalar.Abs(X + Y), Assumptions.None));
    }

    [Fact]
    public void Sums_and_products_of_non_negative_parts_are_recognized_exactly()
    {
        var nonNegative = Assumptions.None.WithMinimum("x", 0).WithMinimum("y", 0);
        Assert.Same(X * X + Y, _cas.Simplify(Scalar.Abs(X * X + Y), Assumptions.None.WithMinimum("y", 0)));
        Assert.Same(X * Y, _cas.Simplify(Scalar.Abs(X * Y), nonNegative));
        Assert.Same(Scalar.Sqrt(X) + Y, _cas.Simplify(Scalar.Abs(Scalar.Sqrt(X) + Y), nonNegative));
        Assert.True(nonNegative.BoundsOf(X * X * Y + Scalar.Exp(-X)).IsNonNegative);
        Assert.False(Assumptions.None.BoundsOf(X * Y).IsNonNegative);
    }

    [Fact]
    public void Square_roots_multiplied_by_themselves_give_their_argument()
    {
        var root = Scalar.Sqrt(X + Y);
        Assert.Same(X + Y, _cas.Simplify(root * root, Assumptions.None));
        Assert.Same((X + Y) * root, _cas.Simplify(root * root * root, Assumptions.None));
        Assert.Same(Scalar.Reciprocal(X + Y), _cas.Simplify(Scalar.One / (root * root), Assumptions.None));
        Assert.Same(X * X, _cas.Simplify(Scalar.Abs(X) * Scalar.Abs(X), Assumptions.None));
    }

    [Fact]
    public void Square_factors_leave_a_square_root()
    {
        var simplified = _cas.Simplify(Scalar.Sqrt(Scalar.Constant(4) * X * X * Y), Assumptions.None.WithMinimum("x", 1));
        Assert.Same(Scalar.Scale(X * Scalar.Sqrt(Y), 2), simplified);
    }

    [Fact]
    public void Common_square_factors_of_a_sum_leave_the_root()
    {
        // |a v| for v = (x, y): sqrt(a^2 x^2 + a^2 y^2) = |a| sqrt(x^2 + y^2).
        var a = Scalar.Variable("a");
        var norm = Scalar.Sqrt(a * a * X * X + a * a * Y * Y);
        Assert.Same(Scalar.Abs(a) * Scalar.Sqrt(X * X + Y * Y), _cas.Simplify(norm, Assumptions.None));
        Assert.Same(a * Scalar.Sqrt(X * X + Y * Y), _cas.Simplify(norm, Assumptions.None.WithMinimum("a", 0)));
        // A square content comes out in the canonical form already.
        Assert.Same(Scalar.Scale(Scalar.Sqrt(X + Y), 2), Scalar.Sqrt(Scalar.Scale(X + Y, 4)));
        Assert.Same(Scalar.Scale(Scalar.Sqrt(X + Y), new Rational(1, 3)), Scalar.Sqrt(Scalar.Scale(X + Y, new Rational(1, 9))));
    }

    [Fact]
    public void Exponentials_combine_and_log_exp_cancel()
    {
        var product = Scalar.Exp(X) * Scalar.Exp(Y) / Scalar.Exp(Scalar.Scale(Y, 2));
        Assert.Same(Scalar.Exp(X - Y), _cas.Simplify(product, Assumptions.None));
        Assert.Same(X + Y, Scalar.Log(Scalar.Exp(X + Y)));
        var positive = Assumptions.None.WithMinimum("x", new Rational(1, 1000));
        Assert.Same(X, _cas.Simplify(Scalar.Exp(Scalar.Log(X)), positive));
        Assert.Same(Scalar.Exp(Scalar.Log(X)), _cas.Simplify(Scalar.Exp(Scalar.Log(X)), Assumptions.None));
    }

    [Fact]
    public void Sine_over_cosine_becomes_tangent()
    {
        Assert.Same(Scalar.Tan(X) * Y, _cas.Simplify(Scalar.Sin(X) * Y / Scalar.Cos(X), Assumptions.None));
    }

    [Fact]
    public void Thesis_normal_vector_example_simplifies_with_the_identity()
    {
        // w4 = u1 v2 - u2 v1 with u1 = v2 = sin(x), u2 = v1 = cos(x) (thesis §4.2).
        var sin = Scalar.Sin(X);
        var cos = Scalar.Cos(X);
        var w4 = sin * sin - cos * cos;
        var simplified = _cas.Simplify(w4, Assumptions.None);
        Assert.Same(Scalar.One - Scalar.Scale(cos * cos, 2), simplified);
    }

    [Fact]
    public void Simplification_preserves_values_on_the_assumed_domain()
    {
        var assumptions = Assumptions.None.WithBounds("x", new Rational(1, 2), 3).WithBounds("y", -2, -1);
        var expressions = new[]
        {
            Scalar.Sqrt(X * X * Y * Y) + Scalar.Abs(X * Y - Scalar.Constant(7)),
            Scalar.Exp(X) * Scalar.Exp(Y) * Scalar.Sin(Y) / Scalar.Cos(Y) + Scalar.Pow(Scalar.Sqrt(X), 5),
            Scalar.Sin(X) * Scalar.Sin(X) * Y - Scalar.Abs(Scalar.Log(X) - Scalar.Constant(5)),
        };
        var values = new Dictionary<string, double> { ["x"] = 1.7, ["y"] = -1.2 };
        foreach (var e in expressions)
        {
            var simplified = _cas.Simplify(e, assumptions);
            Assert.Equal(e.Evaluate(values), simplified.Evaluate(values), 1e-12);
        }
    }

    [Fact]
    public void Interval_bounds_enclose_sampled_values()
    {
        var assumptions = Assumptions.None.WithBounds("x", -2, 3).WithBounds("y", new Rational(1, 4), 5);
        var e = X * X * Y - Scalar.Sqrt(Y) / (Y + Scalar.One) + Scalar.Exp(-X) * Scalar.Sin(Y);
        var bounds = assumptions.BoundsOf(e);
        var random = new Random(17);
        for (var i = 0; i < 500; i++)
        {
            var values = new Dictionary<string, double> { ["x"] = -2 + 5 * random.NextDouble(), ["y"] = 0.25 + 4.75 * random.NextDouble() };
            Assert.True(bounds.Contains(e.Evaluate(values)), $"{e.Evaluate(values)} outside {bounds}");
        }
    }
}
