using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Passes;
using static GMac.Core.CodeGeneration.ExprFactory;
using static GMac.Core.Tests.CodeGeneration.PassTestBlocks;

namespace GMac.Core.Tests.CodeGeneration;

public class LongLatencyFirstPass_Behaviour
{
    private static readonly Expr U = Variable("u"), V = Variable("v"), W = Variable("w"), R = Variable("r");

    private static string[] Order(CodeBlock block) => block.Statements.Cast<AssignmentStatement>().Select(s => s.Target).ToArray();

    [Fact]
    public void A_division_and_the_statements_it_needs_move_first_and_the_rest_keeps_its_order()
    {
        // u and v lead only to outputs; w feeds the division r; the outputs read both.
        var before = Block(
            Temp("u", Sum(A, Negate(B))),
            Temp("v", Sum(C, Negate(D))),
            Temp("w", Sum(Product(A, A), Product(B, B))),
            Out("o1", Product(U, V)),
            Temp("r", Quotient(ConstantExpr.One, Sum(W, Product(C, C)))),
            Out("o2", Product(R, U)),
            Out("o3", Product(R, V)));
        var after = new LongLatencyFirstPass().Run(before);
        AssertSameOutputs(before, after);
        Assert.Equal(["w", "r", "u", "v", "o1", "o2", "o3"], Order(after));
        Assert.Equal(before.Statistics(), after.Statistics());
    }

    [Fact]
    public void Square_roots_and_calls_count_as_long_too()
    {
        var before = Block(
            Temp("u", Product(A, B)),
            Out("o1", Product(U, C)),
            Temp("v", Sum(C, D)),
            Out("o2", Call("sqrt", Product(V, V))));
        var after = new LongLatencyFirstPass().Run(before);
        AssertSameOutputs(before, after);
        Assert.Equal(["v", "o2", "u", "o1"], Order(after));
    }

    [Fact]
    public void A_quotient_of_two_computed_values_moves_only_what_its_denominator_needs()
    {
        // u is the numerator's, w the denominator's: w moves first, the quotient and u keep their order.
        var before = Block(
            Temp("u", Sum(A, Negate(B))),
            Temp("w", Sum(Product(C, C), Product(D, D))),
            Out("o1", Quotient(Product(U, C), W)),
            Out("o2", Quotient(Product(U, D), W)));
        var after = new LongLatencyFirstPass().Run(before);
        AssertSameOutputs(before, after);
        Assert.Equal(["w", "u", "o1", "o2"], Order(after));
    }

    [Fact]
    public void Blocks_without_long_operations_or_not_in_single_assignment_stay_as_they_are()
    {
        var plain = Block(Temp("u", Product(A, B)), Out("o1", Product(U, C)), Temp("v", Sum(C, D)), Out("o2", Product(V, V)));
        Assert.Same(plain, new LongLatencyFirstPass().Run(plain));

        var reassigned = Block(Temp("u", Product(A, B)), Out("o1", Product(U, C)), Temp("u", Quotient(C, D)), Out("o2", Product(U, U)));
        Assert.Same(reassigned, new LongLatencyFirstPass().Run(reassigned));
    }
}
