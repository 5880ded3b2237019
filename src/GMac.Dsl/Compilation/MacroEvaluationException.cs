using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Compilation;

/// <summary>A macro that binds but cannot be evaluated (e.g. the inverse of a null blade).</summary>
public sealed class MacroEvaluationException(SourceSpan span, string message) : Exception(message)
{
    public SourceSpan Span { get; } = span;
}
