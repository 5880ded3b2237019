using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Passes;
using GMac.Core.Numerics;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.Core.Tests.CodeGeneration;

public class TranslationInvariancePass_Behaviour
{
    private static readonly string[] Names = ["ax", "ay", "az", "bx", "by", "bz", "cx", "cy"];
    private static readonly Expr Ax = Variable("ax"), Ay = Variable("ay"), Az = Variable("az");
    private static readonly Expr Bx = Variable("bx"), By = Variable("by"), Bz = Variable("bz");
    private static readonly Expr Cx = Variable("cx"), Cy = Variable("cy");

    private static CodeBlock Block(params (string Name, Expr Value)[] outputs) =>
        new(outputs.Select(o => new AssignmentStatement(o.Name, o.Value, true)),
            Names.ToDictionary(n => n, n => n, StringComparer.Ordinal),
            outputs.ToDictionary(o => o.Name, o => o.Name, StringComparer.Ordinal));

    /// <summary>|a|² − 2a·b + |b|² as the library emitted it: a.x(a.x − 2b.x) + … + b.x² + ….</summary>
    private static Expr ExpandedSquaredDistance() => Sum(
        Product(Ax, Difference(Ax, Product(Constant(2), Bx))),
        Product(Ay, Difference(Ay, Product(Constant(2), By))),
        Product(Az, Difference(Az, Product(Constant(2), Bz))),
        Product(Bx, Bx), Product(By, By), Product(Bz, Bz));

    /// <summary>(b − a) ∧ (c − a) multiplied out: a sum of six products.</summary>
    private static Expr ExpandedSignedArea() => Sum(
        Product(Bx, Cy), Negate(Product(Bx, Ay)), Negate(Product(Ax, Cy)),
        Negate(Product(By, Cx)), Product(By, Ax), Product(Ay, Cx));

    private static Dictionary<string, double> Inputs(Random random, double offset, double spread) =>
        Names.ToDictionary(n => n, _ => offset + spread * (random.NextDouble() * 2 - 1), StringComparer.Ordinal);

    private static void AssertSameValues(CodeBlock before, CodeBlock after)
    {
        var random = new Random(14);
        for (var i = 0; i < 50; i++)
        {
            var inputs = Inputs(random, 0, 3);
            var expected = before.Evaluate(inputs);
            var actual = after.Evaluate(inputs);
            foreach (var (k, v) in expected)
                Assert.True(Math.Abs(v - actual[k]) <= 1e-12 * Math.Max(1, Math.Abs(v)), $"{k}: {v} before, {actual[k]} after");
        }
    }

    [Fact]
    public void Squared_distance_becomes_a_sum_of_squared_differences_in_eight_operations()
    {
        var block = Block(("d2", ExpandedSquaredDistance()));
        Assert.Equal(17, block.Statistics().Operations);
        var optimized = Optimizer.Optimize(block);
        Assert.Equal(8, optimized.Statistics().Operations);
        Assert.Equal(new[] { "ax", "ay", "az", "bx", "by", "bz" }.Order(), VariablesRead(optimized).Order());
        AssertSameValues(block, optimized);
    }

    [Fact]
    public void Squared_distance_of_close_points_far_from_the_origin_keeps_its_accuracy()
    {
        var block = Block(("d2", ExpandedSquaredDistance()));
        var optimized = Optimizer.Optimize(block);
        var random = new Random(2);
        var worstBefore = 0.0;
        for (var i = 0; i < 20; i++)
        {
            // points near 1e4, 1e-3 apart
            var inputs = Inputs(random, 1e4, 1);
            foreach (var (a, b) in new[] { ("ax", "bx"), ("ay", "by"), ("az", "bz") }) inputs[b] = inputs[a] + 1e-3 * (random.NextDouble() - 0.5);
            var exact = Exact(inputs);
            worstBefore = Math.Max(worstBefore, Math.Abs(block.Evaluate(inputs)["d2"] - exact) / exact);
            Assert.InRange(Math.Abs(optimized.Evaluate(inputs)["d2"] - exact) / exact, 0, 1e-15);
        }
        Assert.True(worstBefore > 1e-3, $"the expanded form was accurate to {worstBefore:e2} on these inputs");
    }

    [Fact]
    public void An_expanded_signed_area_reads_differences_to_one_vertex_in_seven_operations()
    {
        var block = Block(("s", ExpandedSignedArea()));
        var result = new TranslationInvariancePass().Run(block);
        var optimized = Optimizer.Optimize(block);
        Assert.Equal(7, optimized.Statistics().Operations);
        // every product multiplies two differences
        var products = result.Outputs.Single().Value.DescendantsAndSelf().OfType<ProductExpr>().ToArray();
        Assert.NotEmpty(products);
        Assert.All(products, p => Assert.All(p.Children, f => Assert.IsType<SumExpr>(f)));
        AssertSameValues(block, result);
        AssertSameValues(block, optimized);
    }

    [Fact]
    public void Groups_of_three_shifted_together_are_found_for_each_axis()
    {
        Assert.True(PolynomialLiftingProbe(ExpandedSignedArea(), out var groups));
        Assert.Equal(2, groups.Count);
        Assert.Contains(groups, g => g.Order().SequenceEqual(new[] { "ax", "bx", "cx" }));
        Assert.Contains(groups, g => g.Order().SequenceEqual(new[] { "ay", "by", "cy" }));
    }

    [Fact]
    public void A_polynomial_that_changes_under_every_shift_is_left_as_it_is()
    {
        var block = Block(("o", Sum(Product(Ax, Bx), Product(Ay, By), Cx)), ("q", Difference(Product(Ax, Ax), Product(Bx, Bx))));
        var result = new TranslationInvariancePass().Run(block);
        Assert.Equal(block.Outputs.Select(o => o.Value), result.Outputs.Select(o => o.Value));
    }

    [Fact]
    public void A_linear_difference_is_left_as_it_is()
    {
        var block = Block(("o", Sum(Ax, Negate(Bx), Cx, Negate(Cy))));
        var result = new TranslationInvariancePass().Run(block);
        Assert.Same(block.Outputs.Single().Value, result.Outputs.Single().Value);
    }

    [Fact]
    public void An_invariant_sum_inside_a_quotient_is_rewritten_and_the_quotient_kept()
    {
        var block = Block(("o", Quotient(ExpandedSquaredDistance(), Sum(Cx, Constant(5)))));
        var result = new TranslationInvariancePass().Run(block);
        Assert.IsType<QuotientExpr>(result.Outputs.Single().Value);
        Assert.True(result.Statistics().Operations < block.Statistics().Operations);
        AssertSameValues(block, result);
    }

    private static bool PolynomialLiftingProbe(Expr e, out List<List<string>> groups)
    {
        Assert.True(PolynomialLifting.TryLift(e, out var polynomial));
        groups = TranslationGroups.Find(polynomial, Names);
        return groups.Count > 0;
    }

    private static IEnumerable<string> VariablesRead(CodeBlock block) =>
        block.Statements.SelectMany(s => s.Expressions).SelectMany(e => e.DescendantsAndSelf()).OfType<VariableExpr>()
            .Select(v => v.Name).Where(Names.Contains).Distinct();

    private static double Exact(Dictionary<string, double> x)
    {
        var sum = Rational.Zero;
        foreach (var (a, b) in new[] { ("ax", "bx"), ("ay", "by"), ("az", "bz") })
        {
            var d = Rational.FromDouble(x[a]) - Rational.FromDouble(x[b]);
            sum += d * d;
        }
        return sum.ToDouble();
    }
}
