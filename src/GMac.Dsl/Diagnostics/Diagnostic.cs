namespace GMac.Dsl.Diagnostics;

/// <summary>
/// One problem found in GMacDSL sources, binding points or the files holding them, printed in
/// the MSBuild format <c>path(line,col): error GMAC0123: message</c>.
/// </summary>
public sealed record Diagnostic(DiagnosticDescriptor Descriptor, SourceSpan Span, string Message)
{
    public string Code => Descriptor.Code;
    public DiagnosticSeverity Severity => Descriptor.Severity;
    public bool IsError => Severity == DiagnosticSeverity.Error;

    /// <summary>
    /// Where in the GMacDSL source the problem comes from, when that is not where it is reported:
    /// a division by zero or an operation too large, found while generating a binding point.
    /// </summary>
    public SourceSpan? Cause { get; init; }

    public override string ToString() =>
        $"{Span.FilePath}({Span.Line},{Span.Column}): {(IsError ? "error" : "warning")} {Code}: {Message}";
}
