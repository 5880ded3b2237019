using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Passes;
using static GMac.Core.CodeGeneration.ExprFactory;
using static GMac.Core.Tests.CodeGeneration.PassTestBlocks;

namespace GMac.Core.Tests.CodeGeneration;

public class OptimizerPasses_Behaviour
{
    [Fact]
    public void Constant_folding_folds_and_propagates()
    {
        var block = Block(
            Temp("t", Sum(Product(Constant(2), Constant(3)), Call("sqrt", Constant(4)))),
            Out("o", Product(Variable("t"), A)));
        var folded = new ConstantFoldingPass().Run(block);
        Assert.Empty(folded.Temporaries);
        Assert.Equal("8.0 * a", folded.Outputs.Single().Value.ToString());
        AssertSameOutputs(block, folded);
    }

    [Fact]
    public void Copy_propagation_reads_the_copied_variable()
    {
        var block = Block(Temp("t", Negate(A)), Out("o", Product(Variable("t"), B)));
        var result = new CopyPropagationPass().Run(block);
        Assert.Empty(result.Temporaries);
        Assert.Equal("-(a * b)", result.Outputs.Single().Value.ToString());
        AssertSameOutputs(block, result);
    }

    [Fact]
    public void Inline_single_use_substitutes_without_expanding()
    {
        var block = Block(Temp("t", Sum(A, B)), Out("o", Product(Variable("t"), C)));
        var result = new InlineSingleUsePass().Run(block);
        Assert.Empty(result.Temporaries);
        Assert.Equal("(a + b) * c", result.Outputs.Single().Value.ToString());
        Assert.Equal(1, result.Statistics().Multiplications);
        AssertSameOutputs(block, result);
    }

    [Fact]
    public void Inline_single_use_keeps_shared_temporaries()
    {
        var block = Block(Temp("t", Sum(A, B)), Out("o1", Product(Variable("t"), C)), Out("o2", Product(Variable("t"), D)));
        Assert.Single(new InlineSingleUsePass().Run(block).Temporaries);
    }

    [Fact]
    public void Common_subexpressions_become_one_temporary_including_negated_differences()
    {
        var block = Block(
            Out("o1", Product(Difference(A, B), C)),
            Out("o2", Product(Difference(B, A), D)),
            Out("o3", Sum(Product(Difference(A, B), C), D)));
        var result = new CommonSubexpressionPass().Run(block);
        Assert.True(result.Statistics().Operations < block.Statistics().Operations, result.ToString());
        // t = a − b; p = t·c; o1 = p; o2 = −t·d; o3 = p + d: four operations instead of seven
        Assert.Equal(4, result.Statistics().Operations);
        Assert.Equal(2, result.Temporaries.Count());
        AssertSameOutputs(block, result);
    }

    [Fact]
    public void Dead_code_removes_unread_temporaries()
    {
        var block = Block(Temp("t", Sum(A, B)), Temp("u", Product(Variable("t"), C)), Out("o", D));
        var result = new DeadCodePass().Run(block);
        Assert.Single(result.Statements);
        AssertSameOutputs(block, result);
    }

    [Fact]
    public void Strength_reduction_turns_powers_into_products_and_shares_reciprocals()
    {
        var s = Sum(A, B);
        var block = Block(
            Out("o1", Power(C, 2)),
            Out("o2", Quotient(C, s)),
            Out("o3", Quotient(D, s)),
            Out("o4", Quotient(A, Constant(4))));
        var result = new StrengthReductionPass().Run(block);
        var stats = result.Statistics();
        Assert.Equal(1, stats.Divisions); // one reciprocal of a + b, read twice
        Assert.Contains(result.Outputs, o => o.Value.ToString() == "c * c");
        Assert.Contains(result.Outputs, o => o.Value.ToString() == "0.25 * a");
        AssertSameOutputs(block, result);
    }

    [Fact]
    public void Temporary_reuse_gives_names_back_after_their_last_read()
    {
        var block = Block(
            Temp("t1", Sum(A, B)),
            Temp("t2", Product(Variable("t1"), Variable("t1"))),
            Temp("t3", Sum(C, D)),
            Temp("t4", Product(Variable("t3"), Variable("t3"))),
            Out("o", Sum(Variable("t2"), Variable("t4"))));
        var result = new TemporaryReusePass().Run(block);
        var names = result.Temporaries.Select(t => t.Target).Distinct().Count();
        Assert.True(names < 4, result.ToString());
        AssertSameOutputs(block, result);
    }

    [Fact]
    public void Sum_factoring_takes_a_shared_factor_out_of_the_terms()
    {
        var block = Block(Out("o", Sum(Product(A, B), Product(A, C), Negate(Product(A, D)), B)));
        var result = new SumFactoringPass().Run(block);
        Assert.Equal(1, result.Statistics().Multiplications);
        AssertSameOutputs(block, result);
    }

    [Fact]
    public void Optimizer_keeps_values_on_random_blocks()
    {
        var random = new Random(81);
        Expr Leaf() => random.Next(5) switch { 0 => A, 1 => B, 2 => C, 3 => D, _ => Constant(random.Next(1, 5)) };
        Expr Tree(int depth) => depth == 0 ? Leaf() : random.Next(6) switch
        {
            0 => Sum(Tree(depth - 1), Tree(depth - 1)),
            1 => Difference(Tree(depth - 1), Tree(depth - 1)),
            2 => Product(Tree(depth - 1), Tree(depth - 1)),
            3 => Quotient(Tree(depth - 1), Sum(Tree(depth - 1), Constant(10))),
            4 => Power(Tree(depth - 1), 2),
            _ => Call("sqrt", Sum(Power(Tree(depth - 1), 2), Constant(1))),
        };
        for (var trial = 0; trial < 30; trial++)
        {
            var shared = Tree(2);
            var block = Block(
                Temp("t", shared),
                Out("o1", Sum(Tree(3), Product(Variable("t"), Tree(1)))),
                Out("o2", Difference(Tree(3), Variable("t"))),
                Out("o3", Product(shared, Tree(2))));
            var optimized = Optimizer.Optimize(block, reuseTemporaries: true);
            AssertSameOutputs(block, optimized);
            Assert.True(optimized.Statistics().Cost <= block.Statistics().Cost, $"{block}\n=>\n{optimized}");
        }
    }
}
