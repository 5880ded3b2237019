namespace GMac.Core.CodeGeneration;

/// <summary>t1 + t2 + …; a subtraction is a term wrapped in <see cref="NegateExpr"/>.</summary>
public sealed class SumExpr : Expr
{
    private readonly Expr[] _terms;

    public SumExpr(IReadOnlyList<Expr> terms) : base(CombineHashes(3, terms))
    {
        if (terms.Count < 2) throw new ArgumentException("A sum needs at least two terms.", nameof(terms));
        _terms = terms.ToArray();
    }

    public override IReadOnlyList<Expr> Children => _terms;
    public override Expr WithChildren(IReadOnlyList<Expr> children) => new SumExpr(children);
    protected override bool SameNode(Expr other) => true;
}
