using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Rewrites;
using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

/// <summary>
/// Results remembered across calls (atom rewrites per assumptions, reduced atoms per relation set,
/// lowered argument trees) must equal what a fresh computation gives, whatever was asked before.
/// </summary>
public class RememberedResults_Agreement
{
    private static List<Scalar> RandomScalars(int seed, int count, int depth)
    {
        var trees = new RandomExpressionTrees(seed);
        var list = new List<Scalar>();
        for (var i = 0; i < count; i++) list.Add(trees.Next(depth).Symbolic);
        return list;
    }

    [Fact]
    public void Simplifier_answers_as_a_fresh_one_after_questions_under_other_assumptions()
    {
        var bounded = Assumptions.None.WithMinimum("x0", Rational.Zero).WithMaximum("x1", Rational.Zero);
        var related = Assumptions.None.WithRelation(Scalar.Variable("x2") * Scalar.Variable("x2"), Scalar.One - Scalar.Variable("x0"), Scalar.Variable("x2") * Scalar.Variable("x2"));
        Assumptions[] choices = [Assumptions.None, bounded, related];
        var shared = new RuleBasedCas();
        var expressions = RandomScalars(seed: 31, count: 150, depth: 4);
        for (var i = 0; i < expressions.Count; i++)
        {
            // the same expression under each set of assumptions, in an order that varies
            for (var k = 0; k < choices.Length; k++)
            {
                var assumptions = choices[(i + k) % choices.Length];
                var fresh = new RuleBasedCas().Simplify(expressions[i], assumptions);
                Assert.Same(fresh, shared.Simplify(expressions[i], assumptions));
            }
        }
    }

    [Fact]
    public void Simplifier_answers_as_a_fresh_one_on_subexpressions_of_earlier_questions()
    {
        var shared = new RuleBasedCas();
        var assumptions = Assumptions.None.WithMinimum("x2", Rational.One);
        foreach (var e in RandomScalars(seed: 32, count: 80, depth: 5))
        {
            Assert.Same(new RuleBasedCas().Simplify(e, assumptions), shared.Simplify(e, assumptions));
            foreach (var atom in e.Atoms().Where(a => a.Arguments.Count > 0))
            foreach (var argument in atom.Arguments)
                Assert.Same(new RuleBasedCas().Simplify(argument, assumptions), shared.Simplify(argument, assumptions));
        }
    }

    [Fact]
    public void Reused_side_relations_reduce_as_a_freshly_built_set()
    {
        var x0 = Scalar.Variable("x0");
        var x1 = Scalar.Variable("x1");
        SideRelations Build() => SideRelations.Trigonometric.With(x0 * x0, Scalar.One - x1 * x1, x0 * x0);
        var shared = Build();
        foreach (var e in RandomScalars(seed: 33, count: 150, depth: 4))
        {
            // inside a root too, so that reduced arguments are remembered and asked for again
            var value = e + Scalar.Sqrt(x0 * x0 + x1 * x1 + e * e);
            Assert.Same(Build().Reduce(value), shared.Reduce(value));
            Assert.Same(Build().Reduce(e), shared.Reduce(e));
        }
    }

    [Fact]
    public void Substituting_into_expressions_whose_functions_do_not_read_the_variable_agrees_numerically()
    {
        var trees = new RandomExpressionTrees(seed: 34);
        var x0 = Scalar.Variable("x0");
        var replacement = Scalar.Variable("x1") - Scalar.Variable("x2");
        for (var n = 0; n < 100; n++)
        {
            // functions read only x1 and x2; x0 appears as a polynomial factor beside them
            var (inner, _) = trees.Next(depth: 3);
            var free = inner.Substitute("x0", Scalar.Constant(new Rational(3, 2)));
            var value = x0 * x0 * free + x0 + Scalar.Sin(free);
            var substituted = value.Substitute("x0", replacement);
            Assert.DoesNotContain("x0", substituted.Variables);
            var point = trees.Point();
            // the unsubstituted value evaluated with x0 set to x1 − x2
            var expected = value.Evaluate(RandomExpressionTrees.Lookup([point[1] - point[2], point[1], point[2]]));
            var actual = substituted.Evaluate(RandomExpressionTrees.Lookup(point));
            Assert.True(Math.Abs(actual - expected) <= 1e-9 * Math.Max(1, Math.Abs(expected)), $"{value}: {actual} vs {expected}");
            Assert.Same(free, free.Substitute("x0", replacement));
        }
    }

    [Fact]
    public void Lowered_trees_shared_between_expressions_evaluate_to_each_expression()
    {
        var trees = new RandomExpressionTrees(seed: 35);
        var denominator = Scalar.Variable("x0") * Scalar.Variable("x0") + Scalar.Variable("x1") * Scalar.Variable("x1") + Scalar.One;
        for (var n = 0; n < 100; n++)
        {
            var (numerator, direct) = trees.Next(depth: 3);
            var value = numerator / denominator + Scalar.Sqrt(denominator);
            var point = trees.Point();
            var variables = RandomExpressionTrees.VariableNames.Select((name, i) => (name, i)).ToDictionary(p => p.name, p => point[p.i]);
            var d = point[0] * point[0] + point[1] * point[1] + 1;
            var expected = direct(point) / d + Math.Sqrt(d);
            foreach (var tree in new[] { ScalarLowering.Lower(value), ScalarLowering.Lower(value, new Dictionary<Atom, int>()) })
            {
                var actual = ExprEvaluator.Evaluate(tree, variables);
                Assert.True(Math.Abs(actual - expected) <= 1e-9 * Math.Max(1, Math.Abs(expected)), $"{value}: {actual} vs {expected}");
            }
        }
    }

    [Fact]
    public void A_division_is_skipped_only_when_its_quotient_would_be_zero()
    {
        var random = new Random(36);
        Scalar[] atoms = [Scalar.Variable("a"), Scalar.Variable("b"), Scalar.Variable("c"), Scalar.Sin(Scalar.Variable("c")), Scalar.Reciprocal(Scalar.Variable("a") + Scalar.One)];
        Scalar Polynomial(int terms, int degree)
        {
            var sum = Scalar.Zero;
            for (var t = 0; t < terms; t++)
            {
                Scalar term = random.Next(-4, 5) is var k && k == 0 ? 1 : k;
                for (var d = random.Next(degree + 1); d > 0; d--) term *= atoms[random.Next(atoms.Length)];
                sum += term;
            }
            return sum;
        }
        var skipped = 0;
        for (var trial = 0; trial < 200; trial++)
        {
            var s = Polynomial(1 + random.Next(4), 2);
            var b = random.Next(2) == 0 ? Polynomial(1 + random.Next(10), 3) : Polynomial(1 + random.Next(4), 1) * s + Polynomial(random.Next(4), 3);
            if (s.IsConstant || Scalar.IsZero(b)) continue;
            foreach (var first in PolynomialRemainder.Candidates(s))
            {
                if (PolynomialRemainder.CanDivide(b, s, first)) continue;
                skipped++;
                Assert.True(!PolynomialRemainder.TryDivide(b, s, first, out var q, out _) || Scalar.IsZero(q), $"{b} / {s} led by {first}");
            }
        }
        Assert.True(skipped > 20, $"only {skipped} divisions were skipped");
    }
}
