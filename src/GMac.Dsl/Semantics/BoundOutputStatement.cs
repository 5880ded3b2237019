using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary>Target-language text copied to the generated code; <c>&lt;mv.blade&gt;</c> references are resolved.</summary>
public sealed record BoundOutputStatement(string Text, IReadOnlyList<BoundCoefficient> References, SourceSpan Span)
    : BoundStatement(Span);
