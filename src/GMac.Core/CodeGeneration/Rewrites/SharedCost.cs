namespace GMac.Core.CodeGeneration.Rewrites;

/// <summary>
/// The weighted cost of a block with every repeated subexpression counted once: roughly what
/// common-subexpression elimination can bring it down to. A fully expanded block repeats
/// sqrt(|a|²) or a shared difference in every term, so its plain cost overstates what it will
/// cost once optimized; this is the fairer figure for deciding whether optimizing it is worth it.
/// </summary>
public static class SharedCost
{
    public static long Of(CodeBlock block)
    {
        var seen = new HashSet<Expr>();
        long cost = 0;
        foreach (var s in block.Statements)
        foreach (var e in s.Expressions)
        foreach (var node in e.DescendantsAndSelf())
        {
            if (node.IsLeaf || !seen.Add(node)) continue;
            cost += node switch
            {
                SumExpr sum => sum.Children.Count - 1,
                ProductExpr p => p.Children.Count - 1,
                QuotientExpr => 4,
                PowerExpr pw => Math.Abs(pw.Exponent) - 1 + (pw.Exponent < 0 ? 4 : 0),
                CallExpr => 8,
                _ => 0,
            };
        }
        return cost;
    }
}
