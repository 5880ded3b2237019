using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary><c>diff(A, x.&lt;1&gt;)</c>: derivative of every coefficient of A with respect to one coefficient.</summary>
public sealed record BoundDifferentiation(BoundExpression Operand, BoundCoefficient Variable, ExpressionType Type, SourceSpan Span)
    : BoundExpression(Type, Span);
