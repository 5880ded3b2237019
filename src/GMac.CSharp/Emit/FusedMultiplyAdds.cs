using GMac.Core.CodeGeneration;

namespace GMac.CSharp.Emit;

/// <summary>
/// Contracts a product added to or subtracted from a sum into one fused multiply–add, written as a
/// call of the neutral function <c>fma</c>(a, b, c) = a·b + c rounded once. In each sum the last
/// product term is fused (a deterministic choice: the same block always prints the same code);
/// the rest of the sum becomes the addend and is contracted in turn, so a sum of products becomes
/// a chain of fused operations. A subtracted product fuses with its first factor negated (exact).
/// </summary>
internal static class FusedMultiplyAdds
{
    public const string Function = "fma";

    public static Expr Contract(Expr e)
    {
        if (e.Children.Count == 0) return e;
        var children = e.Children.Select(Contract).ToList();
        var node = children.SequenceEqual(e.Children) ? e : e.WithChildren(children);
        return node is SumExpr sum ? ContractSum(sum.Children) : node;
    }

    /// <summary>The terms (already contracted inside) as a sum with its last product fused.</summary>
    private static Expr ContractSum(IReadOnlyList<Expr> terms)
    {
        var last = -1;
        for (var i = terms.Count - 1; i >= 0 && last < 0; i--)
            if (ProductOf(terms[i]) is not null) last = i;
        if (last < 0) return terms.Count == 1 ? terms[0] : new SumExpr(terms);
        var (factors, negated) = ProductOf(terms[last])!.Value;
        var rest = terms.Where((_, i) => i != last).ToList();
        var addend = rest.Count == 1 ? rest[0] : ContractSum(rest);
        var left = factors.Count == 2 ? factors[0] : new ProductExpr(factors.Take(factors.Count - 1).ToList());
        if (negated) left = Negated(left);
        return new CallExpr(Function, [left, factors[^1], addend]);
    }

    /// <summary>The factors of a product term, and whether the term subtracts it.</summary>
    private static (IReadOnlyList<Expr> Factors, bool Negated)? ProductOf(Expr term) => term switch
    {
        ProductExpr p => (p.Children, false),
        NegateExpr { Operand: ProductExpr p } => (p.Children, true),
        _ => null,
    };

    private static Expr Negated(Expr e) => e switch
    {
        NegateExpr n => n.Operand,
        ConstantExpr { Exact: { } r } => ConstantExpr.From(-r),
        ConstantExpr c => new ConstantExpr(-c.Value),
        _ => new NegateExpr(e),
    };
}
