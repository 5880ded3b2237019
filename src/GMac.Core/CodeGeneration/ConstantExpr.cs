using GMac.Core.Numerics;

namespace GMac.Core.CodeGeneration;

/// <summary>A numeric constant; exact when it came from a rational.</summary>
public sealed class ConstantExpr : Expr
{
    public double Value { get; }
    public Rational? Exact { get; }

    public ConstantExpr(double value, Rational? exact = null) : base(StableHash.Combine(1, StableHash.Of(value)), [])
    {
        Value = value;
        Exact = exact;
    }

    public static ConstantExpr From(Rational r) => new(r.ToDouble(), r);

    public static readonly ConstantExpr Zero = From(Rational.Zero);
    public static readonly ConstantExpr One = From(Rational.One);

    public override Expr WithChildren(IReadOnlyList<Expr> children) => this;
    protected override bool SameNode(Expr other) => ((ConstantExpr)other).Value.Equals(Value);
}
