using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary><c>A.&lt;e1^e2&gt;</c>: one coefficient of a multivector, as a scalar (sign of the written order included).</summary>
public sealed record BoundCoefficient(BoundExpression Operand, BladeReference Blade, SourceSpan Span)
    : BoundExpression(ExpressionType.Scalar, Span);
