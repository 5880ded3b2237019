using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

public class Scalar_Derivative
{
    private static readonly Scalar X = Scalar.Variable("x");
    private static readonly Scalar Y = Scalar.Variable("y");

    public static TheoryData<string, Scalar> OneExpressionPerAtomKind() => new()
    {
        { "variable", X * X * Y - Scalar.Scale(Y, 3) },
        { "pi", Scalar.Pi * X * X },
        { "sin", Scalar.Sin(X * Y) },
        { "cos", Scalar.Cos(X * X - Y) },
        { "tan", Scalar.Tan(X / 3) },
        { "sqrt", Scalar.Sqrt(X * X + Y * Y) },
        { "exp", Scalar.Exp(X * Y) },
        { "log", Scalar.Log(X + Y * Y) },
        { "atan2", Scalar.Atan2(Y, X) },
        { "abs", Scalar.Abs(X - Scalar.Scale(Y, 2)) },
        { "pow", Scalar.Pow(X, Y) },
        { "pow-rational", Scalar.Cbrt(X - Scalar.Constant(3)) },
        { "inverse", Scalar.One / (X + Y) },
        { "negative power", Scalar.Pow(X, -3) * Y },
    };

    [Theory]
    [MemberData(nameof(OneExpressionPerAtomKind))]
    public void Derivative_matches_central_difference_for_every_atom_kind(string kind, Scalar f)
    {
        var random = new Random(kind.Length * 31 + 5);
        foreach (var variable in new[] { "x", "y" })
        {
            var derivative = f.Derivative(variable);
            for (var k = 0; k < 10; k++)
            {
                var point = new Dictionary<string, double> { ["x"] = 0.5 + 1.5 * random.NextDouble(), ["y"] = 0.3 + random.NextDouble() };
                AssertMatchesDifference(f, derivative, variable, point, kind);
            }
        }
    }

    [Fact]
    public void Derivative_matches_central_difference_on_random_trees()
    {
        var trees = new RandomExpressionTrees(seed: 99);
        for (var n = 0; n < 150; n++)
        {
            var (f, _) = trees.Next(depth: 3);
            var point = trees.Point();
            var values = new Dictionary<string, double>();
            for (var i = 0; i < point.Length; i++) values[RandomExpressionTrees.VariableNames[i]] = point[i];
            foreach (var variable in RandomExpressionTrees.VariableNames)
                AssertMatchesDifference(f, f.Derivative(variable), variable, values, f.ToString());
        }
    }

    [Fact]
    public void Derivatives_are_exact_where_they_can_be()
    {
        Assert.Same(Scalar.Scale(X * Y, 2), (X * X * Y).Derivative("x"));
        Assert.Same(Scalar.Cos(X), Scalar.Sin(X).Derivative("x"));
        Assert.Same(Scalar.Zero, Scalar.Sin(Y).Derivative("x"));
        Assert.Same(Scalar.Scale(Scalar.Pow(X, -2), -1), Scalar.Reciprocal(X).Derivative("x"));
        Assert.Same(Scalar.Constant(new Rational(1, 2)) / Scalar.Sqrt(X), Scalar.Sqrt(X).Derivative("x"));
    }

    private static void AssertMatchesDifference(Scalar f, Scalar derivative, string variable, Dictionary<string, double> point, string label)
    {
        const double h = 1e-5;
        double At(double offset)
        {
            var moved = new Dictionary<string, double>(point) { [variable] = point[variable] + offset };
            return f.Evaluate(moved);
        }
        var numeric = (At(h) - At(-h)) / (2 * h);
        var symbolic = derivative.Evaluate(point);
        var scale = Math.Max(1, Math.Max(Math.Abs(numeric), Math.Abs(At(0))));
        Assert.True(Math.Abs(symbolic - numeric) <= 1e-6 * scale, $"{label}: d/d{variable} = {derivative}; {symbolic} vs {numeric}");
    }
}
