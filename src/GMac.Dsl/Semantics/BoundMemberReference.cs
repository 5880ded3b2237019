using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary><c>&lt;x&gt;</c>: a member of the bound target-language object (class bindings only).</summary>
public sealed record BoundMemberReference(string Path, SourceSpan Span) : BoundExpression(ExpressionType.Scalar, Span);
