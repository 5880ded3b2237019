using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Accuracy;
using GMac.Core.Numerics;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.Core.Tests.CodeGeneration;

public class AccuracyProbe_Choice
{
    private static readonly Expr Ax = Variable("ax"), Bx = Variable("bx"), Ay = Variable("ay"), By = Variable("by");

    private static CodeBlock Block(Expr value) =>
        new([new AssignmentStatement("o", value, true)],
            new[] { "ax", "bx", "ay", "by" }.ToDictionary(n => n, n => n, StringComparer.Ordinal),
            new Dictionary<string, string> { ["o"] = "o" });

    /// <summary>(a − b)² + (c − d)² multiplied out, as a sum of squares minus twice the cross products.</summary>
    private static CodeBlock Expanded() => Block(Sum(
        Product(Ax, Ax), Product(Bx, Bx), Negate(Product(Constant(2), Ax, Bx)),
        Product(Ay, Ay), Product(By, By), Negate(Product(Constant(2), Ay, By))));

    private static CodeBlock Differences()
    {
        var dx = Difference(Ax, Bx);
        var dy = Difference(Ay, By);
        return Block(Sum(Product(dx, dx), Product(dy, dy)));
    }

    [Fact]
    public void The_expanded_form_loses_accuracy_near_a_large_common_value_and_the_difference_form_does_not()
    {
        Assert.True(AccuracyProbe.Error(Expanded()) > AccuracyProbe.Threshold);
        Assert.InRange(AccuracyProbe.Error(Differences())!.Value, 0, 1e-15);
    }

    [Fact]
    public void A_cheaper_but_far_less_accurate_candidate_gives_way_and_a_comparable_one_does_not()
    {
        Assert.Equal(1, AccuracyProbe.MostAccurateAffordable([Expanded(), Differences()]));
        Assert.Equal(0, AccuracyProbe.MostAccurateAffordable([Differences(), Expanded()]));
        Assert.Equal(0, AccuracyProbe.MostAccurateAffordable([Block(Product(Ax, By)), Block(Product(By, Ax))]));
    }

    [Fact]
    public void Stopping_at_an_accurate_cheapest_candidate_chooses_as_probing_every_candidate_would()
    {
        CodeBlock[] pool = [Expanded(), Differences(), Block(Product(Ax, By)), Block(Call("sqrt", Ax)), Block(Sum(Product(Ax, Ax), Negate(Product(Bx, Bx))))];
        foreach (var a in pool)
        foreach (var b in pool)
        foreach (var c in pool)
        {
            CodeBlock[] candidates = [a, b, c];
            // the rule on every candidate's error: the first not far above the best known error
            var errors = candidates.Select(AccuracyProbe.Error).ToArray();
            var known = errors.Where(e => e is not null).Select(e => e!.Value).ToArray();
            var limit = known.Length < 2 ? double.PositiveInfinity : Math.Max(AccuracyProbe.Threshold, AccuracyProbe.Factor * known.Min());
            var expected = Array.FindIndex(errors, e => e is null || e <= limit);

            Assert.Equal(expected, AccuracyProbe.MostAccurateAffordable(candidates));
        }
    }

    [Fact]
    public void Blocks_with_math_calls_or_a_zero_division_are_not_judged()
    {
        Assert.Null(AccuracyProbe.Error(Block(Call("sqrt", Ax))));
        Assert.Null(AccuracyProbe.Error(Block(Quotient(Ax, Difference(By, By)))));
        Assert.Equal(0, AccuracyProbe.MostAccurateAffordable([Block(Call("sqrt", Ax)), Differences()]));
    }

    [Fact]
    public void Exact_evaluation_is_exact_and_declines_what_it_cannot_do()
    {
        var third = new Rational(1, 3);
        var block = Block(Quotient(Sum(Ax, Bx), Ay));
        var inputs = new Dictionary<string, Rational> { ["ax"] = third, ["bx"] = third, ["ay"] = 2, ["by"] = 0 };
        Assert.Equal(third, ExactEvaluator.Evaluate(block, inputs)!["o"]);
        Assert.Null(ExactEvaluator.Evaluate(Block(Quotient(Ax, By)), inputs));
        Assert.Null(ExactEvaluator.Evaluate(Block(Call("sin", Ax)), inputs));
        Assert.Equal(Rational.One, ExactEvaluator.Evaluate(Block(Call("sin", Ax)), inputs, (_, _) => Rational.One)!["o"]);
    }
}
