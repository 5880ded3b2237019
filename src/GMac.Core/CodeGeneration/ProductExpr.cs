namespace GMac.Core.CodeGeneration;

/// <summary>f1 · f2 · …</summary>
public sealed class ProductExpr : Expr
{
    private readonly Expr[] _factors;

    public ProductExpr(IReadOnlyList<Expr> factors) : base(CombineHashes(4, factors))
    {
        if (factors.Count < 2) throw new ArgumentException("A product needs at least two factors.", nameof(factors));
        _factors = factors.ToArray();
    }

    public override IReadOnlyList<Expr> Children => _factors;
    public override Expr WithChildren(IReadOnlyList<Expr> children) => new ProductExpr(children);
    protected override bool SameNode(Expr other) => true;
}
