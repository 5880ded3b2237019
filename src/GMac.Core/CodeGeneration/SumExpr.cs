namespace GMac.Core.CodeGeneration;

/// <summary>t1 + t2 + …; a subtraction is a term wrapped in <see cref="NegateExpr"/>.</summary>
public sealed class SumExpr : Expr
{
    public SumExpr(IReadOnlyList<Expr> terms) : this(terms.ToArray())
    {
    }

    private SumExpr(Expr[] terms) : base(CombineHashes(3, terms), terms)
    {
        if (terms.Length < 2) throw new ArgumentException("A sum needs at least two terms.", nameof(terms));
    }

    public override Expr WithChildren(IReadOnlyList<Expr> children) => new SumExpr(children);
    protected override bool SameNode(Expr other) => true;
}
