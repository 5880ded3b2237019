namespace GMac.Core.CodeGeneration;

/// <summary>numerator / denominator.</summary>
public sealed class QuotientExpr : Expr
{
    public Expr Numerator { get; }
    public Expr Denominator { get; }

    public QuotientExpr(Expr numerator, Expr denominator) : base(CombineHashes(5, [numerator, denominator]))
    {
        Numerator = numerator;
        Denominator = denominator;
    }

    public override IReadOnlyList<Expr> Children => [Numerator, Denominator];
    public override Expr WithChildren(IReadOnlyList<Expr> children) => new QuotientExpr(children[0], children[1]);
    protected override bool SameNode(Expr other) => true;
}
