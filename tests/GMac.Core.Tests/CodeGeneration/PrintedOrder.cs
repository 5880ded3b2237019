using GMac.Core.CodeGeneration;

namespace GMac.Core.Tests.CodeGeneration;

/// <summary>
/// Evaluates a block in the order its printed text computes it: a sum's positive terms first (as
/// the printer writes them), then left to right, so results compare bit for bit with the C#.
/// </summary>
internal static class PrintedOrder
{
    public static IReadOnlyDictionary<string, double> Evaluate(CodeBlock block, IReadOnlyDictionary<string, double> inputs)
    {
        var values = new Dictionary<string, double>(inputs, StringComparer.Ordinal);
        var outputs = new Dictionary<string, double>(StringComparer.Ordinal);
        foreach (var s in block.Statements.OfType<AssignmentStatement>())
        {
            var v = Evaluate(s.Value, values);
            values[s.Target] = v;
            if (s.IsOutput) outputs[s.Target] = v;
        }
        return outputs;
    }

    private static double Evaluate(Expr e, IReadOnlyDictionary<string, double> values)
    {
        if (e is not SumExpr s) return e.IsLeaf ? ExprEvaluator.Evaluate(e, values) : Node(e, values);
        var sum = 0.0;
        var first = true;
        foreach (var t in s.Children.OrderBy(t => t is NegateExpr || t is ConstantExpr { Value: < 0 } ? 1 : 0))
        {
            var v = Evaluate(t, values);
            sum = first ? v : sum + v;
            first = false;
        }
        return sum;
    }

    private static double Node(Expr e, IReadOnlyDictionary<string, double> values) => e switch
    {
        ProductExpr p => p.Children.Skip(1).Aggregate(Evaluate(p.Children[0], values), (acc, c) => acc * Evaluate(c, values)),
        QuotientExpr q => Evaluate(q.Numerator, values) / Evaluate(q.Denominator, values),
        NegateExpr n => -Evaluate(n.Operand, values),
        _ => ExprEvaluator.Evaluate(e.WithChildren(e.Children.Select(c => (Expr)new ConstantExpr(Evaluate(c, values))).ToArray()), values),
    };
}
