using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

public sealed record BoundJoinStatement(bool IsOn, SourceSpan Span) : BoundStatement(Span);
