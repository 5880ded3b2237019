using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Passes;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.Core.Tests.CodeGeneration;

/// <summary>Sums whose value is a sum of squares of named temporaries read those temporaries.</summary>
public class SumOfSquaresPass_Rewrite
{
    private static readonly string[] Names = ["ax", "ay", "az", "bx", "by", "bz", "cx", "cy", "cz"];
    private static readonly Expr[] A = [Variable("ax"), Variable("ay"), Variable("az")];
    private static readonly Expr[] B = [Variable("bx"), Variable("by"), Variable("bz")];
    private static readonly Expr[] C = [Variable("cx"), Variable("cy"), Variable("cz")];

    private static CodeBlock Block(params AssignmentStatement[] statements) =>
        new(statements, Names.ToDictionary(n => n, n => n, StringComparer.Ordinal),
            statements.Where(s => s.IsOutput).ToDictionary(s => s.Target, s => s.Target, StringComparer.Ordinal));

    private static Expr Square(Expr x) => Product(x, x);
    private static Expr Dot(Expr[] u, Expr[] v) => Sum(u.Zip(v, (x, y) => Product(x, y)));

    /// <summary>nᵢ = (a × b)ᵢ named, s = (n·c) / (|a|²|b|² − (a·b)²) with the denominator as written.</summary>
    private static CodeBlock ProjectionOnTheNormal(Expr denominator) => Block(
        new AssignmentStatement("n0", Difference(Product(A[1], B[2]), Product(A[2], B[1])), false),
        new AssignmentStatement("n1", Difference(Product(A[2], B[0]), Product(A[0], B[2])), false),
        new AssignmentStatement("n2", Difference(Product(A[0], B[1]), Product(A[1], B[0])), false),
        new AssignmentStatement("s", Quotient(Sum(Product(Variable("n0"), C[0]), Product(Variable("n1"), C[1]), Product(Variable("n2"), C[2])), denominator), true));

    private static Expr Lagrange() => Difference(Product(Sum(A.Select(Square)), Sum(B.Select(Square))), Square(Dot(A, B)));

    private static void AssertSameValues(CodeBlock before, CodeBlock after)
    {
        var random = new Random(22);
        for (var i = 0; i < 50; i++)
        {
            var inputs = Names.ToDictionary(n => n, _ => random.NextDouble() * 4 - 2, StringComparer.Ordinal);
            var expected = before.Evaluate(inputs);
            var actual = after.Evaluate(inputs);
            foreach (var (k, v) in expected)
                Assert.True(Math.Abs(v - actual[k]) <= 1e-9 * Math.Max(1, Math.Abs(v)), $"{k}: {v} before, {actual[k]} after");
        }
    }

    [Fact]
    public void Squared_norm_of_a_wedge_reads_the_named_cross_product()
    {
        var block = ProjectionOnTheNormal(Lagrange());

        var rewritten = new SumOfSquaresPass().Run(block);

        // n (6 mul, 3 add), n·c (3 mul, 2 add), n·n (3 mul, 2 add), one division
        var stats = rewritten.Statistics();
        Assert.Equal((7, 12, 1), (stats.Additions, stats.Multiplications, stats.Divisions));
        AssertSameValues(block, rewritten);
    }

    [Fact]
    public void A_constant_multiple_of_the_squares_keeps_its_factor()
    {
        // 2|a|²|b|² − 2(a·b)², a sum whose value is twice the squares
        var block = ProjectionOnTheNormal(Difference(Product(Constant(2), Sum(A.Select(Square)), Sum(B.Select(Square))), Product(Constant(2), Square(Dot(A, B)))));

        var rewritten = new SumOfSquaresPass().Run(block);

        var stats = rewritten.Statistics();
        Assert.Equal((7, 13, 1), (stats.Additions, stats.Multiplications, stats.Divisions));
        AssertSameValues(block, rewritten);
    }

    [Fact]
    public void A_sum_that_is_not_the_squares_is_left_alone()
    {
        // |a|²|b|² + (a·b)²: one sign away from |a × b|²
        var block = ProjectionOnTheNormal(Sum(Product(Sum(A.Select(Square)), Sum(B.Select(Square))), Square(Dot(A, B))));

        Assert.Same(block, new SumOfSquaresPass().Run(block));
    }

    [Fact]
    public void Squares_already_written_as_squares_are_left_alone()
    {
        // t1² + t0² equals the squares of the pair read by o, at the same cost: no gain, no rewrite
        var (t0, t1) = (Variable("t0"), Variable("t1"));
        var block = Block(
            new AssignmentStatement("t0", Dot(A, B), false),
            new AssignmentStatement("t1", Dot(A, C), false),
            new AssignmentStatement("o", Sum(t0, t1), true),
            new AssignmentStatement("p", Sum(Square(t1), Square(t0)), true));

        Assert.Same(block, new SumOfSquaresPass().Run(block));
    }
}
