namespace GMac.Core.CodeGeneration;

/// <summary>−operand.</summary>
public sealed class NegateExpr : Expr
{
    public Expr Operand { get; }

    public NegateExpr(Expr operand) : base(CombineHashes(6, [operand])) => Operand = operand;

    public override IReadOnlyList<Expr> Children => [Operand];
    public override Expr WithChildren(IReadOnlyList<Expr> children) => new NegateExpr(children[0]);
    protected override bool SameNode(Expr other) => true;
}
