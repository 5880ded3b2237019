namespace GMac.Core.CodeGeneration;

/// <summary>A call of a math function by its neutral name (sin, cos, tan, acos, sqrt, exp, log, atan2, abs, pow).</summary>
public sealed class CallExpr : Expr
{
    public string Function { get; }

    public CallExpr(string function, IReadOnlyList<Expr> arguments) : this(function, arguments.ToArray())
    {
    }

    private CallExpr(string function, Expr[] arguments) : base(StableHash.Combine(CombineHashes(8, arguments), StableHash.Of(function)), arguments) => Function = function;

    public override Expr WithChildren(IReadOnlyList<Expr> children) => new CallExpr(Function, children);
    protected override bool SameNode(Expr other) => ((CallExpr)other).Function == Function;
}
