namespace GMac.Dsl.Diagnostics;

/// <summary>
/// Collects diagnostics; one method per kind so that each code and message is
/// written in exactly one place.
/// </summary>
public sealed class DiagnosticBag
{
    private readonly List<Diagnostic> _items = [];

    public IReadOnlyList<Diagnostic> Items => _items;
    public bool HasErrors => _items.Any(d => d.IsError);

    public void AddRange(IEnumerable<Diagnostic> diagnostics) => _items.AddRange(diagnostics);

    private void Error(string code, SourceSpan span, string message) =>
        _items.Add(new Diagnostic(code, DiagnosticSeverity.Error, message, span));

    private void Warning(string code, SourceSpan span, string message) =>
        _items.Add(new Diagnostic(code, DiagnosticSeverity.Warning, message, span));

    // ---- input and syntax
    public void ReportSyntaxError(SourceSpan span, string message) => Error("GMAC0001", span, message);
    public void ReportNestingTooDeep(SourceSpan span, int limit) =>
        Error("GMAC0002", span, $"expression nested deeper than {limit} levels");
    public void ReportCannotRead(SourceSpan span, string reason) => Error("GMAC0003", span, reason);

    // ---- names
    public void ReportUnknownName(SourceSpan span, string kind, string name, string? suggestion) =>
        Error("GMAC0101", span, suggestion is null
            ? $"unknown {kind} '{name}'"
            : $"unknown {kind} '{name}'; did you mean '{suggestion}'?");
    public void ReportDuplicate(SourceSpan span, string kind, string name, SourceSpan previous) =>
        Error("GMAC0102", span, $"{kind} '{name}' is already defined at {previous.FilePath}({previous.Line},{previous.Column})");
    public void ReportWrongKind(SourceSpan span, string name, string actual, string expected) =>
        Error("GMAC0103", span, $"'{name}' is {actual}, not {expected}");

    // ---- macros
    public void ReportFrameMismatch(SourceSpan span, string leftFrame, string rightFrame) =>
        Error("GMAC0110", span, $"operands belong to different frames '{leftFrame}' and '{rightFrame}'");
    public void ReportAssignToInput(SourceSpan span, string name) =>
        Error("GMAC0111", span, $"cannot assign to input '{name}'");
    public void ReportOutputReadBeforeAssignment(SourceSpan span, string name) =>
        Error("GMAC0112", span, $"output '{name}' is read before it is assigned");
    public void ReportOutputClassMismatch(SourceSpan span, string name, string className, string reason) =>
        Error("GMAC0113", span, $"value assigned to '{name}' does not fit class '{className}': {reason}");
    public void ReportCyclicCall(SourceSpan span, string cycle) =>
        Error("GMAC0114", span, $"macro calls form a cycle: {cycle}");
    public void ReportUsedBeforeAssignment(SourceSpan span, string name) =>
        Error("GMAC0115", span, $"'{name}' is used before it is assigned");
    public void ReportTypeError(SourceSpan span, string message) => Error("GMAC0116", span, message);
    public void ReportCallError(SourceSpan span, string message) => Error("GMAC0117", span, message);

    // ---- frames, transforms, matrices
    public void ReportNotInvertible(SourceSpan span, string name) =>
        Error("GMAC0120", span, $"transform '{name}' is not invertible, so 'inverse of' cannot be used");
    public void ReportMatrixSize(SourceSpan span, int rows, int columns, int expected) =>
        Error("GMAC0121", span, $"matrix is {rows}x{columns} but must be {expected}x{expected}");
    public void ReportNonSymmetricIpm(SourceSpan span, int row, int column) =>
        Error("GMAC0122", span, $"inner product matrix is not symmetric: entry ({row},{column}) differs from ({column},{row})");
    public void ReportDefinitionCycle(SourceSpan span, string kind, string cycle) =>
        Error("GMAC0123", span, $"{kind} definitions form a cycle: {cycle}");
    public void ReportInvalidDefinition(SourceSpan span, string message) => Error("GMAC0124", span, message);
    public void ReportEmptyLimits(SourceSpan span, string binding, string member, string min, string max) =>
        Error("GMAC0125", span, $"class binding '{binding}' limits '{member}' to at least {min} and at most {max}: no value satisfies both");

    // ---- scalar expressions
    public void ReportInvalidScalar(SourceSpan span, string message) =>
        Error("GMAC0130", span, $"invalid scalar expression: {message}");
    public void ReportDivisionByZero(SourceSpan span, string divisor) =>
        Error("GMAC0131", span, $"division by zero: '{divisor}' evaluates to zero");
    public void ReportNoRealValue(SourceSpan span, string expression, double value) =>
        Error("GMAC0132", span, $"'{expression}' has no finite real value (it evaluates to {(double.IsNaN(value) ? "NaN" : value > 0 ? "infinity" : "-infinity")})");

    // ---- evaluation
    public static Diagnostic EvaluationError(SourceSpan span, string message) =>
        new("GMAC0140", DiagnosticSeverity.Error, $"cannot evaluate: {message}", span);

    // ---- warnings
    public void ReportUnused(SourceSpan span, string kind, string name) =>
        Warning("GMAC0201", span, $"{kind} '{name}' is never used");
    public void ReportOutputNeverAssigned(SourceSpan span, string macro, string name) =>
        Warning("GMAC0202", span, $"output '{name}' of macro '{macro}' is never assigned");
    public void ReportSkippedFile(SourceSpan span, string reason) => Warning("GMAC0203", span, reason);
}
