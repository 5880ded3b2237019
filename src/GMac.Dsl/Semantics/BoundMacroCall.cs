using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary>A call of a one-output macro used as an expression; arguments follow the input order.</summary>
public sealed record BoundMacroCall(MacroSymbol Macro, IReadOnlyList<BoundExpression> Arguments, ExpressionType Type, SourceSpan Span)
    : BoundExpression(Type, Span);
