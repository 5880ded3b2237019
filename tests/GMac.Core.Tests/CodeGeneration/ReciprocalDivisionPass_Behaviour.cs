using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Passes;
using static GMac.Core.CodeGeneration.ExprFactory;
using static GMac.Core.Tests.CodeGeneration.PassTestBlocks;

namespace GMac.Core.Tests.CodeGeneration;

public class ReciprocalDivisionPass_Behaviour
{
    private static readonly Expr U = Variable("u"), R = Variable("r");

    [Fact]
    public void Products_with_a_reciprocal_become_divisions_by_its_denominator()
    {
        var before = Block(
            Temp("u", Sum(A, Negate(B))),
            Temp("r", Quotient(ConstantExpr.One, Sum(Product(C, C), Product(D, D)))),
            Out("o1", Product(R, U, C)),
            Out("o2", Negate(Product(R, Sum(U, D)))),
            Out("o3", R));
        var after = new ReciprocalDivisionPass().Run(before);
        AssertSameOutputs(before, after);
        var (b, a) = (before.Statistics(), after.Statistics());
        Assert.Equal((1, 3), (b.Divisions, a.Divisions));
        Assert.Equal(b.Multiplications - 2, a.Multiplications);
        Assert.DoesNotContain(after.Statements, s => s is AssignmentStatement { Value: QuotientExpr { Numerator: ConstantExpr { Value: 1 } }, IsOutput: false });
    }

    [Fact]
    public void A_reciprocal_of_a_name_leaves_no_statement_of_its_own()
    {
        var before = Block(
            Temp("u", Sum(Product(A, A), Product(B, B))),
            Temp("r", Quotient(ConstantExpr.One, U)),
            Out("o1", Product(R, C)),
            Out("o2", Product(R, D)));
        var after = new ReciprocalDivisionPass().Run(before);
        AssertSameOutputs(before, after);
        Assert.Equal(["u", "o1", "o2"], after.Statements.Cast<AssignmentStatement>().Select(s => s.Target));
        Assert.Equal(2, after.Statistics().Divisions);
    }

    [Fact]
    public void A_product_holding_the_reciprocal_twice_leaves_the_block_as_it_is()
    {
        var block = Block(
            Temp("r", Quotient(ConstantExpr.One, Sum(C, D))),
            Out("o1", Product(R, R, A)));
        Assert.Same(block, new ReciprocalDivisionPass().Run(block));
    }
}
