using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

public abstract record BoundStatement(SourceSpan Span);
