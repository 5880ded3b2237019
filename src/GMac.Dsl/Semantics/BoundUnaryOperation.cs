using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

public sealed record BoundUnaryOperation(UnaryOperator Operator, BoundExpression Operand, ExpressionType Type, SourceSpan Span)
    : BoundExpression(Type, Span);
