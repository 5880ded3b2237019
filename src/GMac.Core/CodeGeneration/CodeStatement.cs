namespace GMac.Core.CodeGeneration;

/// <summary>One statement of a code block, in execution order.</summary>
public abstract record CodeStatement
{
    /// <summary>The expressions this statement reads.</summary>
    public abstract IReadOnlyList<Expr> Expressions { get; }

    /// <summary>The same statement over rewritten expressions (same count and order).</summary>
    public abstract CodeStatement WithExpressions(IReadOnlyList<Expr> expressions);
}

/// <summary><c>Target = Value</c>: a temporary (single assignment) or an output coefficient.</summary>
public sealed record AssignmentStatement(string Target, Expr Value, bool IsOutput) : CodeStatement
{
    public override IReadOnlyList<Expr> Expressions => [Value];
    public override CodeStatement WithExpressions(IReadOnlyList<Expr> expressions) => this with { Value = expressions[0] };
}

/// <summary>
/// Text copied into the generated code (the DSL's <c>output {…}</c> statement), with expressions
/// where it named multivector coefficients.
/// </summary>
public sealed record VerbatimStatement(IReadOnlyList<VerbatimPart> Parts) : CodeStatement
{
    public override IReadOnlyList<Expr> Expressions => Parts.Where(p => p.Value is not null).Select(p => p.Value!).ToArray();

    public override CodeStatement WithExpressions(IReadOnlyList<Expr> expressions)
    {
        var i = 0;
        return new VerbatimStatement(Parts.Select(p => p.Value is null ? p : p with { Value = expressions[i++] }).ToArray());
    }
}

/// <summary>Either literal text or an expression to print in its place.</summary>
public sealed record VerbatimPart(string? Text, Expr? Value)
{
    public static VerbatimPart Literal(string text) => new(text, null);
    public static VerbatimPart Expression(Expr value) => new(null, value);
}
