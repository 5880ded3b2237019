namespace GMac.Core.CodeGeneration;

/// <summary>f1 · f2 · …</summary>
public sealed class ProductExpr : Expr
{
    public ProductExpr(IReadOnlyList<Expr> factors) : this(factors.ToArray())
    {
    }

    private ProductExpr(Expr[] factors) : base(CombineHashes(4, factors), factors)
    {
        if (factors.Length < 2) throw new ArgumentException("A product needs at least two factors.", nameof(factors));
    }

    public override Expr WithChildren(IReadOnlyList<Expr> children) => new ProductExpr(children);
    protected override bool SameNode(Expr other) => true;
}
