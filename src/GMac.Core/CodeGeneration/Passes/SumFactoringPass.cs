namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Distributive factoring of expression trees: a factor shared by several terms of a sum is
/// taken out, a·x + a·y − a·z → a·(x + y − z), one multiplication saved for each extra term that
/// shares it. Lowering from symbolic form already factors; this pass catches what later passes
/// (temporaries, common subexpressions) make shareable.
/// </summary>
public sealed class SumFactoringPass : IOptimizerPass
{
    public string Name => "sum factoring";

    public CodeBlock Run(CodeBlock block) =>
        BlockRewriting.MapExpressions(block, e => BlockRewriting.ReplaceNodes(e, node => node is SumExpr s ? Factor(s) : null));

    private static Expr Factor(SumExpr sum)
    {
        var terms = sum.Children.Select(Split).ToList();
        var best = BestFactor(terms);
        if (best is null)
        {
            // nothing shared at this level: factor inside the terms
            var rebuilt = sum.Children.Select(c => BlockRewriting.ReplaceNodes(c, n => n is SumExpr inner && !ReferenceEquals(inner, sum) ? Factor(inner) : null)).ToArray();
            return rebuilt.SequenceEqual(sum.Children, ReferenceEqualityComparer.Instance) ? sum : ExprFactory.Sum(rebuilt);
        }
        var with = new List<Expr>();
        var without = new List<Expr>();
        foreach (var (factors, negated, original) in terms)
        {
            var index = factors.FindIndex(f => f.Equals(best));
            if (index < 0) { without.Add(original); continue; }
            var rest = factors.Where((_, k) => k != index).ToList();
            var cofactor = ExprFactory.Product(rest);
            with.Add(negated ? ExprFactory.Negate(cofactor) : cofactor);
        }
        var inner = ExprFactory.Sum(with);
        if (inner is SumExpr innerSum) inner = Factor(innerSum);
        var factored = ExprFactory.Product(best, inner);
        if (without.Count == 0) return factored;
        var remaining = ExprFactory.Sum(without);
        if (remaining is SumExpr remainingSum) remaining = Factor(remainingSum);
        return ExprFactory.Sum(factored, remaining);
    }

    /// <summary>A term as its factors (a product's children, or the term itself) and its sign.</summary>
    private static (List<Expr> Factors, bool Negated, Expr Original) Split(Expr term)
    {
        var negated = term is NegateExpr;
        var body = term is NegateExpr n ? n.Operand : term;
        var factors = body is ProductExpr p ? p.Children.ToList() : [body];
        return (factors, negated, term);
    }

    /// <summary>The non-constant factor found in the most terms (at least two), first seen on ties.</summary>
    private static Expr? BestFactor(List<(List<Expr> Factors, bool Negated, Expr Original)> terms)
    {
        var counts = new Dictionary<Expr, int>();
        var order = new List<Expr>();
        foreach (var (factors, _, _) in terms)
        foreach (var f in factors.Distinct())
        {
            if (f is ConstantExpr) continue;
            if (counts.TryGetValue(f, out var c)) counts[f] = c + 1;
            else { counts[f] = 1; order.Add(f); }
        }
        Expr? best = null;
        var bestCount = 1;
        foreach (var f in order)
            if (counts[f] > bestCount) { best = f; bestCount = counts[f]; }
        // taking a factor out of terms that are that factor alone saves nothing (a + a·x = a·(1 + x))
        if (best is not null && terms.Count(t => t.Factors.Count > 1 && t.Factors.Contains(best)) < 2) return null;
        return best;
    }
}
