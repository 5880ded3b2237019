namespace GMac.Core.CodeGeneration;

/// <summary>base^exponent for an integer exponent; strength reduction turns it into products.</summary>
public sealed class PowerExpr : Expr
{
    public Expr Base { get; }
    public int Exponent { get; }

    public PowerExpr(Expr @base, int exponent) : this([@base], exponent)
    {
    }

    private PowerExpr(Expr[] children, int exponent) : base(StableHash.Combine(CombineHashes(7, children), exponent), children)
    {
        Base = children[0];
        Exponent = exponent;
    }

    public override Expr WithChildren(IReadOnlyList<Expr> children) => new PowerExpr(children[0], Exponent);
    protected override bool SameNode(Expr other) => ((PowerExpr)other).Exponent == Exponent;
}
