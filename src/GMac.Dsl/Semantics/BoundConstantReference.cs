using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

public sealed record BoundConstantReference(ConstantSymbol Constant, ExpressionType Type, SourceSpan Span)
    : BoundExpression(Type, Span);
