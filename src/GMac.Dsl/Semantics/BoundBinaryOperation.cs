using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

public sealed record BoundBinaryOperation(BinaryOperator Operator, BoundExpression Left, BoundExpression Right,
    ExpressionType Type, SourceSpan Span) : BoundExpression(Type, Span);
