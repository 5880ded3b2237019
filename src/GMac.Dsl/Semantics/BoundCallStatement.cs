using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

public sealed record BoundCallStatement(MacroSymbol Macro, IReadOnlyList<BoundCallBinding> Bindings, SourceSpan Span)
    : BoundStatement(Span);
