namespace GMac.Core.CodeGeneration;

/// <summary>numerator / denominator.</summary>
public sealed class QuotientExpr : Expr
{
    public Expr Numerator { get; }
    public Expr Denominator { get; }

    public QuotientExpr(Expr numerator, Expr denominator) : this([numerator, denominator])
    {
    }

    private QuotientExpr(Expr[] children) : base(CombineHashes(5, children), children)
    {
        Numerator = children[0];
        Denominator = children[1];
    }

    public override Expr WithChildren(IReadOnlyList<Expr> children) => new QuotientExpr(children[0], children[1]);
    protected override bool SameNode(Expr other) => true;
}
