using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

public class SideRelations_Reduction
{
    private static readonly Scalar W = Scalar.Variable("w");
    private static readonly Scalar X = Scalar.Variable("x");
    private static readonly Scalar Y = Scalar.Variable("y");
    private static readonly Scalar Z = Scalar.Variable("z");

    [Fact]
    public void Sine_squared_plus_cosine_squared_is_one()
    {
        var s = Scalar.Sin(X) * Scalar.Sin(X) + Scalar.Cos(X) * Scalar.Cos(X);
        Assert.NotSame(Scalar.One, s);
        Assert.Same(Scalar.One, SideRelations.Trigonometric.Reduce(s));
        Assert.Same(Scalar.One, new RuleBasedCas().Simplify(s, Assumptions.None));
    }

    [Fact]
    public void One_minus_sine_squared_is_cosine_squared_and_reduction_is_consistent()
    {
        var relations = SideRelations.Trigonometric;
        var cos2 = Scalar.Cos(Y) * Scalar.Cos(Y);
        Assert.Same(cos2, relations.Reduce(Scalar.One - Scalar.Sin(Y) * Scalar.Sin(Y)));
        // Two different spellings of the same function reduce to one object.
        var a = Scalar.Pow(Scalar.Sin(Y), 4);
        var b = Scalar.Pow(Scalar.One - cos2, 2);
        Assert.Same(relations.Reduce(b), relations.Reduce(a));
        // Inside arguments too: sqrt(sin^2 + cos^2) → 1.
        Assert.Same(Scalar.One, relations.Reduce(Scalar.Sqrt(Scalar.Sin(X) * Scalar.Sin(X) + Scalar.Cos(X) * Scalar.Cos(X))));
    }

    [Fact]
    public void Reduction_does_not_change_the_value()
    {
        var s = Scalar.Pow(Scalar.Sin(X), 3) * Y + Scalar.Sin(X) * Scalar.Cos(X) - Scalar.Pow(Scalar.Sin(X + Y), 2);
        var reduced = SideRelations.Trigonometric.Reduce(s);
        var values = new Dictionary<string, double> { ["x"] = 0.7, ["y"] = -1.3 };
        Assert.Equal(s.Evaluate(values), reduced.Evaluate(values), 1e-13);
        foreach (var atom in reduced.Atoms())
            Assert.False(atom.Kind == AtomKind.Sin && reduced.Terms.Any(t => t.Monomial.Factors.Any(f => f.Atom == atom && f.Power >= 2)));
    }

    [Fact]
    public void Unit_rotor_diagonal_term_reduces_to_one_minus_two_squares()
    {
        // R = w + x e23 + y e31 + z e12 with w^2 + x^2 + y^2 + z^2 = 1; the e1 coefficient of R e1 R~
        // is w^2 + x^2 - y^2 - z^2 (thesis eq. 7.5), built here by hand.
        var diagonal = W * W + X * X - Y * Y - Z * Z;
        var relations = SideRelations.None.With(W * W + X * X + Y * Y + Z * Z, Scalar.One, W * W);
        var reduced = relations.Reduce(diagonal);
        Assert.Same(Scalar.One - Scalar.Scale(Y * Y, 2) - Scalar.Scale(Z * Z, 2), reduced);
        Assert.Equal("1 - 2*y^2 - 2*z^2", reduced.ToString());
        // The off-diagonal terms (-2wz + 2xy, 2wy + 2xz) have no w^2 and stay as they are.
        var offDiagonal = Scalar.Scale(X * Y - W * Z, 2);
        Assert.Same(offDiagonal, relations.Reduce(offDiagonal));
    }

    [Fact]
    public void Higher_powers_of_the_eliminated_monomial_are_reduced_repeatedly()
    {
        var relations = SideRelations.None.With(W * W + X * X, Scalar.One, W * W);
        var reduced = relations.Reduce(Scalar.Pow(W, 5) + Scalar.Pow(W, 4));
        var expected = Scalar.Pow(Scalar.One - X * X, 2) * (W + Scalar.One);
        Assert.Same(expected, reduced);
        Assert.DoesNotContain(reduced.Terms, t => t.Monomial.Factors.Any(f => f.Atom.Name == "w" && f.Power >= 2));
    }

    [Fact]
    public void Relations_that_do_not_contain_the_monomial_are_rejected()
    {
        var error = Assert.Throws<ArgumentException>(() => SideRelations.None.With(X * X + Y * Y, Scalar.One, W * W));
        Assert.Contains("w^2", error.Message);
        Assert.Throws<ArgumentException>(() => SideRelations.None.With(X * X, X * X * X * X, X * X));
        Assert.Throws<ArgumentException>(() => SideRelations.None.With(X, Scalar.One, X + Y));
    }
}
