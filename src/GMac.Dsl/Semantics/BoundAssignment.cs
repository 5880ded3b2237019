using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

public sealed record BoundAssignment(VariableSymbol Target, BoundExpression Value, SourceSpan Span) : BoundStatement(Span);
