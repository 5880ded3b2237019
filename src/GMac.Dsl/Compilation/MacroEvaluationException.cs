using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Compilation;

/// <summary>
/// A macro that binds but cannot be evaluated (e.g. the inverse of a null blade), at the DSL
/// statement or expression responsible. <see cref="Descriptor"/> is set when the problem has a code
/// of its own (division by zero, an operation too large), otherwise the generic one applies.
/// </summary>
public sealed class MacroEvaluationException(SourceSpan span, string message, DiagnosticDescriptor? descriptor = null, Exception? inner = null)
    : Exception(message, inner)
{
    public SourceSpan Span { get; } = span;
    public DiagnosticDescriptor? Descriptor { get; } = descriptor;
}
