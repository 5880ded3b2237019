namespace GMac.Core.CodeGeneration;

/// <summary>A reference to an input or a temporary of the code block.</summary>
public sealed class VariableExpr : Expr
{
    public string Name { get; }

    public VariableExpr(string name) : base(StableHash.Combine(2, StableHash.Of(name)), []) => Name = name;

    public override Expr WithChildren(IReadOnlyList<Expr> children) => this;
    protected override bool SameNode(Expr other) => ((VariableExpr)other).Name == Name;
}
