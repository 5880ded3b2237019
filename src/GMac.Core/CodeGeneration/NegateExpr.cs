namespace GMac.Core.CodeGeneration;

/// <summary>−operand.</summary>
public sealed class NegateExpr : Expr
{
    public Expr Operand { get; }

    public NegateExpr(Expr operand) : this([operand])
    {
    }

    private NegateExpr(Expr[] children) : base(CombineHashes(6, children), children) => Operand = children[0];

    public override Expr WithChildren(IReadOnlyList<Expr> children) => new NegateExpr(children[0]);
    protected override bool SameNode(Expr other) => true;
}
