using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Passes;
using static GMac.Core.CodeGeneration.ExprFactory;
using static GMac.Core.Tests.CodeGeneration.PassTestBlocks;

namespace GMac.Core.Tests.CodeGeneration;

public class PairExtractionPass_Behaviour
{
    /// <summary>A product or sum of exactly these operands, in any order.</summary>
    private static bool IsOf<TNode>(Expr e, params Expr[] operands) where TNode : Expr =>
        e is TNode && e.Children.Select(c => c.ToString()).Order().SequenceEqual(operands.Select(o => o.ToString()).Order());

    private static AssignmentStatement[] Temporaries(CodeBlock block) =>
        block.Statements.OfType<AssignmentStatement>().Where(s => !s.IsOutput).ToArray();

    [Fact]
    public void A_factor_pair_in_two_products_becomes_one_temporary()
    {
        var block = Block(Out("o1", Product(A, B, C)), Out("o2", Product(A, B, D)));
        var result = new PairExtractionPass().Run(block);
        var temporary = Assert.Single(Temporaries(result));
        Assert.True(IsOf<ProductExpr>(temporary.Value, A, B), temporary.Value.ToString());
        Assert.Equal(4, block.Statistics().Multiplications);
        Assert.Equal(3, result.Statistics().Multiplications);
        AssertSameOutputs(block, result);
    }

    [Fact]
    public void A_term_pair_in_two_sums_becomes_one_temporary_even_when_one_sum_has_it_negated()
    {
        var block = Block(
            Out("o1", Sum(A, B, C)),
            Out("o2", Sum(Negate(A), Negate(B), D)),
            Out("o3", Sum(A, B, Product(C, D))));
        var result = new PairExtractionPass().Run(block);
        var temporary = Assert.Single(Temporaries(result));
        Assert.True(IsOf<SumExpr>(temporary.Value, A, B), temporary.Value.ToString());
        Assert.Equal(6, block.Statistics().Additions);
        Assert.Equal(4, result.Statistics().Additions);
        AssertSameOutputs(block, result);
    }

    [Fact]
    public void The_pair_shared_most_often_goes_first()
    {
        // a·b occurs three times, c·d twice: both become temporaries, a·b as the first.
        var block = Block(
            Out("o1", Product(A, B, C)), Out("o2", Product(A, B, D)), Out("o3", Product(A, B, Sum(C, D))),
            Out("o4", Sum(Product(C, D, A), Product(C, D, Sum(A, B)))));
        var result = new PairExtractionPass().Run(block);
        var temporaries = Temporaries(result);
        Assert.True(IsOf<ProductExpr>(temporaries[0].Value, A, B), temporaries[0].Value.ToString());
        Assert.Contains(temporaries, t => IsOf<ProductExpr>(t.Value, C, D));
        AssertSameOutputs(block, result);
    }

    [Fact]
    public void A_block_without_a_repeated_pair_is_left_as_it_is()
    {
        var block = Block(Out("o1", Product(A, B)), Out("o2", Sum(C, D)), Out("o3", Product(A, C, D)));
        var result = new PairExtractionPass().Run(block);
        Assert.Empty(Temporaries(result));
        Assert.Equal(block.Statistics(), result.Statistics());
    }

    [Fact]
    public void Temporary_names_skip_names_the_block_already_uses()
    {
        var names = new[] { "a", "o1", "fresh" };
        var block = Block(Out("o1", Product(A, B, C)), Out("o2", Product(A, B, D)));
        var result = new PairExtractionPass(i => names[i]).Run(block);
        Assert.Equal("fresh", Assert.Single(Temporaries(result)).Target);
        AssertSameOutputs(block, result);
    }
}
