using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

public sealed record BoundVariableReference(VariableSymbol Variable, ExpressionType Type, SourceSpan Span)
    : BoundExpression(Type, Span);
