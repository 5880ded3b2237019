namespace GMac.Dsl.Diagnostics;

/// <summary>
/// What one diagnostic code means: its severity, a one-line meaning for the documentation, and
/// the commands that can report it. Each code has exactly one descriptor, in <see cref="DiagnosticCodes"/>.
/// </summary>
public sealed record DiagnosticDescriptor(string Code, DiagnosticSeverity Severity, string Meaning, ReportedBy ReportedBy);
