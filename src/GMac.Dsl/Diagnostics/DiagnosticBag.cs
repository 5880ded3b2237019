namespace GMac.Dsl.Diagnostics;

/// <summary>
/// Collects diagnostics of the DSL; one method per kind so that each message is written in
/// exactly one place (the codes themselves are defined in <see cref="DiagnosticCodes"/>).
/// </summary>
public sealed class DiagnosticBag
{
    private readonly List<Diagnostic> _items = [];

    public IReadOnlyList<Diagnostic> Items => _items;
    public bool HasErrors => _items.Any(d => d.IsError);

    public void AddRange(IEnumerable<Diagnostic> diagnostics) => _items.AddRange(diagnostics);

    private void Report(DiagnosticDescriptor descriptor, SourceSpan span, string message) =>
        _items.Add(new Diagnostic(descriptor, span, message));

    // ---- input and syntax
    public void ReportSyntaxError(SourceSpan span, string message) => Report(DiagnosticCodes.SyntaxError, span, message);
    public void ReportNestingTooDeep(SourceSpan span, int limit) =>
        Report(DiagnosticCodes.NestingTooDeep, span, $"expression nested deeper than {limit} levels");
    public void ReportOperatorChainTooLong(SourceSpan span, int limit) =>
        Report(DiagnosticCodes.NestingTooDeep, span, $"expression nests more than {limit} levels deep through products, quotients, powers, signs and brackets; name parts of it");
    public void ReportFileTooLarge(SourceSpan span, int limit) =>
        Report(DiagnosticCodes.FileTooLarge, span, $"the file has more than {limit} tokens (words, numbers and symbols), the most gmac reads from one file; split it");
    public void ReportCannotRead(SourceSpan span, string reason) => Report(DiagnosticCodes.CannotReadDsl, span, reason);

    // ---- names
    public void ReportUnknownName(SourceSpan span, string kind, string name, string? suggestion) =>
        Report(DiagnosticCodes.UnknownName, span, suggestion is null
            ? $"unknown {kind} '{name}'"
            : $"unknown {kind} '{name}'; did you mean '{suggestion}'?");
    public void ReportDuplicate(SourceSpan span, string kind, string name, SourceSpan previous) =>
        Report(DiagnosticCodes.Duplicate, span, $"{kind} '{name}' is already defined at {previous.FilePath}({previous.Line},{previous.Column})");
    public void ReportWrongKind(SourceSpan span, string name, string actual, string expected) =>
        Report(DiagnosticCodes.WrongKind, span, $"'{name}' is {actual}, not {expected}");

    // ---- macros
    public void ReportFrameMismatch(SourceSpan span, string leftFrame, string rightFrame) =>
        Report(DiagnosticCodes.FrameMismatch, span, $"operands belong to different frames '{leftFrame}' and '{rightFrame}'");
    public void ReportAssignToInput(SourceSpan span, string name) =>
        Report(DiagnosticCodes.AssignToInput, span, $"cannot assign to input '{name}'");
    public void ReportOutputReadBeforeAssignment(SourceSpan span, string name) =>
        Report(DiagnosticCodes.OutputReadBeforeAssignment, span, $"output '{name}' is read before it is assigned");
    public void ReportOutputClassMismatch(SourceSpan span, string name, string className, string reason) =>
        Report(DiagnosticCodes.OutputClassMismatch, span, $"value assigned to '{name}' does not fit class '{className}': {reason}");
    public void ReportCyclicCall(SourceSpan span, string cycle) =>
        Report(DiagnosticCodes.CyclicCall, span, $"macro calls form a cycle: {cycle}");
    public void ReportUsedBeforeAssignment(SourceSpan span, string name) =>
        Report(DiagnosticCodes.UsedBeforeAssignment, span, $"'{name}' is used before it is assigned");
    public void ReportTypeError(SourceSpan span, string message) => Report(DiagnosticCodes.TypeError, span, message);
    public void ReportCallError(SourceSpan span, string message) => Report(DiagnosticCodes.CallError, span, message);
    public void ReportNoDual(SourceSpan span, string function, string frame) =>
        Report(DiagnosticCodes.NoDual, span,
            $"'{function}' needs an invertible metric, but frame '{frame}' is degenerate (its pseudoscalar squares to zero); "
            + "use rcomplement(A) (A ∧ rcomplement(A) = I) and lcomplement(A) for duality, and 'vee' for the regressive product (join of points, meet in a dual model)");

    public void ReportGeneralInverseTooLarge(SourceSpan span, string frame, int dimension) =>
        Report(DiagnosticCodes.GeneralInverseTooLarge, span,
            $"'general_inverse' has closed forms up to 5 dimensions, but frame '{frame}' has {dimension}; use inverse(A) for a versor or blade");

    // ---- frames, transforms, matrices
    public void ReportNotInvertible(SourceSpan span, string name) =>
        Report(DiagnosticCodes.NotInvertible, span, $"transform '{name}' is not invertible, so 'inverse of' cannot be used");
    public void ReportMatrixSize(SourceSpan span, int rows, int columns, int expected) =>
        Report(DiagnosticCodes.MatrixSize, span, $"matrix is {rows}x{columns} but must be {expected}x{expected}");
    public void ReportNonSymmetricIpm(SourceSpan span, int row, int column) =>
        Report(DiagnosticCodes.NonSymmetricIpm, span, $"inner product matrix is not symmetric: entry ({row},{column}) differs from ({column},{row})");
    public void ReportDefinitionCycle(SourceSpan span, string kind, string cycle) =>
        Report(DiagnosticCodes.DefinitionCycle, span, $"{kind} definitions form a cycle: {cycle}");
    public void ReportInvalidDefinition(SourceSpan span, string message) => Report(DiagnosticCodes.InvalidDefinition, span, message);
    public void ReportEmptyLimits(SourceSpan span, string binding, string member, string min, string max) =>
        Report(DiagnosticCodes.EmptyLimits, span, $"class binding '{binding}' limits '{member}' to at least {min} and at most {max}: no value satisfies both");

    // ---- scalar expressions
    public void ReportInvalidScalar(SourceSpan span, string message) =>
        Report(DiagnosticCodes.InvalidScalar, span, $"invalid scalar expression: {message}");
    public void ReportDivisionByZero(SourceSpan span, string divisor) =>
        Report(DiagnosticCodes.ConstantDivisionByZero, span, $"division by zero: '{divisor}' evaluates to zero");
    public void ReportNoRealValue(SourceSpan span, string expression, double value) =>
        Report(DiagnosticCodes.NoRealValue, span, $"'{expression}' has no finite real value (it evaluates to {(double.IsNaN(value) ? "NaN" : value > 0 ? "infinity" : "-infinity")})");

    // ---- output blocks
    public void ReportInvalidOutputText(SourceSpan span, string message) => Report(DiagnosticCodes.InvalidOutputText, span, message);

    // ---- warnings
    public void ReportUnused(SourceSpan span, string kind, string name) =>
        Report(DiagnosticCodes.Unused, span, $"{kind} '{name}' is never used");
    public void ReportOutputNeverAssigned(SourceSpan span, string macro, string name) =>
        Report(DiagnosticCodes.OutputNeverAssigned, span, $"output '{name}' of macro '{macro}' is never assigned");
    public void ReportSkippedFile(SourceSpan span, string reason) => Report(DiagnosticCodes.SkippedDslFile, span, reason);
    public void ReportSignatureOrder(SourceSpan span, string message) => Report(DiagnosticCodes.SignatureOrder, span, message);
}
