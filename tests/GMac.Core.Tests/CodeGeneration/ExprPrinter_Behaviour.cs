using GMac.Core.CodeGeneration;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.Core.Tests.CodeGeneration;

public class ExprPrinter_Behaviour
{
    [Fact]
    public void A_sum_nested_after_the_first_term_keeps_its_parentheses_and_so_its_evaluation_order()
    {
        Expr a = Variable("a"), b = Variable("b"), c = Variable("c");
        Assert.Equal("a + (b + c)", new SumExpr([a, new SumExpr([b, c])]).ToString());
        Assert.Equal("a + b + c", new SumExpr([new SumExpr([a, b]), c]).ToString());
        Assert.Equal("c - (a - b)", new SumExpr([c, new NegateExpr(new SumExpr([a, new NegateExpr(b)]))]).ToString());
    }
}
