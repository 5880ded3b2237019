using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

public sealed record BoundTransformApplication(TransformSymbol Transform, BoundExpression Operand, ExpressionType Type, SourceSpan Span)
    : BoundExpression(Type, Span);
