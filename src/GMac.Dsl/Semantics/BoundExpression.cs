using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary>An expression after name resolution and type checking.</summary>
public abstract record BoundExpression(ExpressionType Type, SourceSpan Span);
