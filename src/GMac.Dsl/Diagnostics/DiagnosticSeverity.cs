namespace GMac.Dsl.Diagnostics;

public enum DiagnosticSeverity
{
    Warning,
    Error,
}
