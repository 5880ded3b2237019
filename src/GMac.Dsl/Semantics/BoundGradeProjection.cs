using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

public sealed record BoundGradeProjection(BoundExpression Operand, int Grade, ExpressionType Type, SourceSpan Span)
    : BoundExpression(Type, Span);
