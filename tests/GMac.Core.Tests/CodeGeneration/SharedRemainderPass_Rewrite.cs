using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Passes;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.Core.Tests.CodeGeneration;

/// <summary>Fractions over one denominator that share their division remainder compute it once.</summary>
public class SharedRemainderPass_Rewrite
{
    private static readonly string[] Names = ["ax", "ay", "az", "bx", "by", "bz", "c", "d", "e"];
    private static readonly Expr[] A = [Variable("ax"), Variable("ay"), Variable("az")];
    private static readonly Expr[] B = [Variable("bx"), Variable("by"), Variable("bz")];
    private static readonly Expr C = Variable("c"), D = Variable("d"), E = Variable("e");

    private static CodeBlock Block(params AssignmentStatement[] statements) =>
        new(statements, Names.ToDictionary(n => n, n => n, StringComparer.Ordinal),
            statements.Where(s => s.IsOutput).ToDictionary(s => s.Target, s => s.Target, StringComparer.Ordinal));

    private static Expr Square(Expr x) => Product(x, x);

    /// <summary>The rejection of a from b as the canonical form leaves it: (bᵢ(aⱼ² + aₖ²) − aᵢ(aⱼbⱼ + aₖbₖ))/|a|².</summary>
    private static CodeBlock ExpandedRejection()
    {
        var norm = Sum(A.Select(Square));
        return Block(Enumerable.Range(0, 3).Select(i =>
        {
            var (j, k) = ((i + 1) % 3, (i + 2) % 3);
            var numerator = Difference(Product(B[i], Sum(Square(A[j]), Square(A[k]))), Product(A[i], Sum(Product(A[j], B[j]), Product(A[k], B[k]))));
            return new AssignmentStatement($"w{i}", Quotient(numerator, norm), true);
        }).ToArray());
    }

    private static void AssertSameValues(CodeBlock before, CodeBlock after)
    {
        var random = new Random(21);
        for (var i = 0; i < 50; i++)
        {
            var inputs = Names.ToDictionary(n => n, _ => random.NextDouble() * 4 - 2, StringComparer.Ordinal);
            var expected = before.Evaluate(inputs);
            var actual = after.Evaluate(inputs);
            Assert.Equal(expected.Keys.Order(), actual.Keys.Order());
            foreach (var (k, v) in expected)
                Assert.True(Math.Abs(v - actual[k]) <= 1e-12 * Math.Max(1, Math.Abs(v)), $"{k}: {v} before, {actual[k]} after");
        }
    }

    [Fact]
    public void Expanded_rejection_becomes_b_minus_a_times_one_shared_quotient()
    {
        var block = ExpandedRejection();

        var rewritten = new SharedRemainderPass().Run(block);

        // |a|² (3 mul, 2 add), a·b (3 mul, 2 add), k = a·b / |a|², wᵢ = bᵢ − aᵢ k (3 mul, 3 add)
        var stats = rewritten.Statistics();
        Assert.Equal((7, 9, 1), (stats.Additions, stats.Multiplications, stats.Divisions));
        AssertSameValues(block, rewritten);
    }

    [Fact]
    public void Optimizer_keeps_the_rejection_at_seventeen_operations()
    {
        var block = ExpandedRejection();

        var optimized = Optimizer.Optimize(block);

        Assert.Equal(17, optimized.Statistics().Operations);
        AssertSameValues(block, optimized);
    }

    [Fact]
    public void Fractions_reading_one_reciprocal_with_a_common_remainder_share_it()
    {
        // (c·a + d·b)/(c + d) = a − d·k and (c·b + d·a)/(c + d) = b + d·k, with k = (a − b)·r named once
        var (a, b) = (A[0], B[0]);
        var block = Block(
            new AssignmentStatement("r", Quotient(Constant(1), Sum(C, D)), false),
            new AssignmentStatement("o1", Product(Sum(Product(C, a), Product(D, b)), Variable("r")), true),
            new AssignmentStatement("o2", Product(Sum(Product(C, b), Product(D, a)), Variable("r")), true));

        var rewritten = new SharedRemainderPass().Run(block);

        var stats = rewritten.Statistics();
        Assert.Equal((4, 3, 1), (stats.Additions, stats.Multiplications, stats.Divisions));
        AssertSameValues(block, rewritten);
    }

    [Fact]
    public void Factored_numerators_over_a_shared_reciprocal_are_left_alone()
    {
        // (c + d)⁴(a + b) + (c − d)·a and the same times e, over a + b: both leave b·(c − d) over, but the
        // remainder form would expand (c + d)⁴
        var (a, b) = (A[0], B[0]);
        var cd = Sum(C, D);
        var common = Sum(Product(cd, cd, cd, cd, Sum(a, b)), Product(Difference(C, D), a));
        var block = Block(
            new AssignmentStatement("r", Quotient(Constant(1), Sum(a, b)), false),
            new AssignmentStatement("o1", Product(common, Variable("r")), true),
            new AssignmentStatement("o2", Product(common, E, Variable("r")), true));

        var rewritten = new SharedRemainderPass().Run(block);

        Assert.True(ReferenceEquals(block, rewritten), rewritten.ToString());
    }
}
