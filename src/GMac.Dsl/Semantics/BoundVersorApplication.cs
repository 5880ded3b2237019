using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary><c>apply(V, A)</c> = V A V⁻¹.</summary>
public sealed record BoundVersorApplication(BoundExpression Versor, BoundExpression Operand, ExpressionType Type, SourceSpan Span)
    : BoundExpression(Type, Span);
