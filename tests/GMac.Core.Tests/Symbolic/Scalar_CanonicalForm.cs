using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

public class Scalar_CanonicalForm
{
    private static readonly Scalar X = Scalar.Variable("x");
    private static readonly Scalar Y = Scalar.Variable("y");

    [Fact]
    public void Like_terms_cancel_to_the_interned_variable()
    {
        var result = X + Y - X;
        Assert.Same(Scalar.Variable("y"), result);
        Assert.Same(Scalar.Zero, X - X);
        Assert.True(Scalar.IsZero(X * Y - Y * X));
    }

    [Fact]
    public void Square_of_a_sum_expands_into_three_terms()
    {
        var square = (X + Y) * (X + Y);
        var expected = X * X + Scalar.Scale(X * Y, 2) + Y * Y;
        Assert.Same(expected, square);
        Assert.Equal(3, square.Terms.Count);
        Assert.Same(square, Scalar.Pow(X + Y, 2));
        Assert.Equal("x^2 + 2*x*y + y^2", square.ToString());
    }

    [Fact]
    public void A_variable_times_its_reciprocal_is_one()
    {
        Assert.Same(Scalar.One, X * Scalar.Reciprocal(X));
        Assert.Same(Scalar.One, X / X);
        Assert.Same(Scalar.One, Scalar.Sin(X) * X * X / (X * Scalar.Sin(X) * X));
        Assert.Same(Y, X * Y / X);
    }

    [Fact]
    public void Reciprocal_of_a_sum_is_an_inverse_atom_with_unit_leading_coefficient()
    {
        var inverse = Scalar.One / (Scalar.Scale(X, 2) + Scalar.Scale(Y, 2));
        var term = Assert.Single(inverse.Terms);
        Assert.Equal(new Rational(1, 2), term.Coefficient);
        var factor = Assert.Single(term.Monomial.Factors);
        Assert.Equal(AtomKind.Inverse, factor.Atom.Kind);
        Assert.Same(X + Y, factor.Atom.Arguments[0]);
        Assert.Same(X + Y, Scalar.Reciprocal(Scalar.Reciprocal(X + Y)));
    }

    [Fact]
    public void Independently_built_equal_expressions_are_the_same_object()
    {
        var a = Scalar.Sin(X * Y + 3) * Scalar.Sqrt(X) - Scalar.Constant(new Rational(1, 2));
        var b = Scalar.Constant(new Rational(-1, 2)) + Scalar.Sqrt(Scalar.Variable("x")) * Scalar.Sin(Scalar.Variable("y") * Scalar.Variable("x") + 1 + 2);
        Assert.True(ReferenceEquals(a, b));
        Assert.Equal(a.GetHashCode(), b.GetHashCode());
    }

    [Fact]
    public void Constants_fold_exactly()
    {
        Assert.Same(Scalar.Constant(new Rational(3, 2)), Scalar.Sqrt(Scalar.Constant(new Rational(9, 4))));
        Assert.Same(Scalar.Zero, Scalar.Sin(Scalar.Zero));
        Assert.Same(Scalar.One, Scalar.Cos(Scalar.Zero));
        Assert.Same(Scalar.One, Scalar.Exp(Scalar.Zero));
        Assert.Same(Scalar.Zero, Scalar.Log(Scalar.One));
        Assert.Same(Scalar.Constant(5), Scalar.Abs(Scalar.Constant(-5)));
        Assert.Same(Scalar.NegativeOne, Scalar.Cos(Scalar.Pi));
        Assert.Same(Scalar.Zero, Scalar.Sin(Scalar.Scale(Scalar.Pi, 3)));
        Assert.Same(Scalar.NegativeOne, Scalar.Sin(Scalar.Scale(Scalar.Pi, new Rational(3, 2))));
        Assert.Same(X, Scalar.Log(Scalar.Exp(X)));
        Assert.False(Scalar.Sqrt(Scalar.Constant(2)).IsConstant);
    }

    [Fact]
    public void Odd_and_even_functions_take_a_canonical_sign()
    {
        Assert.Same(-Scalar.Sin(X - Y), Scalar.Sin(Y - X));
        Assert.Same(Scalar.Cos(X - Y), Scalar.Cos(Y - X));
        Assert.Same(-Scalar.Tan(X), Scalar.Tan(-X));
        Assert.Same(Scalar.Scale(Scalar.Abs(X + Y), 2), Scalar.Abs(Scalar.Scale(X + Y, -2)));
        Assert.Same(X * X, Scalar.Abs(X * X));
    }

    [Fact]
    public void Half_integer_powers_become_square_roots()
    {
        Assert.Same(Scalar.Sqrt(X), Scalar.Pow(X, Scalar.Constant(new Rational(1, 2))));
        Assert.Same(Scalar.Pow(Scalar.Sqrt(X), 3), Scalar.Pow(X, Scalar.Constant(new Rational(3, 2))));
        Assert.Equal(AtomKind.Pow, Scalar.Pow(X, Y).Terms[0].Monomial.Factors[0].Atom.Kind);
    }

    [Fact]
    public void Structure_can_be_walked_and_variables_are_collected_through_arguments()
    {
        var s = Scalar.Scale(X * Y, 2) - Scalar.Pow(Scalar.Sin(Scalar.Variable("a")), 2);
        Assert.Equal(2, s.Terms.Count);
        Assert.Equal((Rational)2, s.Terms[0].Coefficient);
        var sinSquared = s.Terms[1].Monomial.Factors[0];
        Assert.Equal(AtomKind.Sin, sinSquared.Atom.Kind);
        Assert.Equal(2, sinSquared.Power);
        Assert.Equal(new[] { "a", "x", "y" }, s.Variables.Order(StringComparer.Ordinal));
        Assert.True(Scalar.Constant(7).TryGetConstant(out var seven) && seven == 7);
        Assert.False(s.IsConstant);
    }

    [Fact]
    public void Invalid_variable_names_are_rejected()
    {
        Assert.Throws<ArgumentException>(() => Scalar.Variable("2x"));
        Assert.Throws<ArgumentException>(() => Scalar.Variable("pi"));
        Assert.Throws<ArgumentException>(() => Scalar.Variable(""));
        Assert.Equal("u.e1", Scalar.Variable("u.e1").ToString());
    }

    [Fact]
    public void Division_by_structural_zero_throws()
    {
        Assert.Throws<DivideByZeroException>(() => X / (Y - Y));
    }

    [Fact]
    public void Interning_is_consistent_across_threads()
    {
        var results = new Scalar[8];
        Parallel.For(0, results.Length, i =>
        {
            var s = Scalar.Zero;
            for (var k = 0; k < 200; k++)
                s += Scalar.Pow(Scalar.Variable($"t{k % 17}") + Scalar.Sin(Scalar.Variable("u")), 2) * Scalar.Constant(k);
            results[i] = s;
        });
        foreach (var r in results) Assert.Same(results[0], r);
    }
}
