using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Generation;

/// <summary>
/// A binding-point problem, at the line of the binding that caused it (or the region's first line).
/// When the cause is in the GMacDSL source instead (a division by zero found while evaluating a
/// macro, an operation too large to generate), <see cref="Source"/> locates it there, and callers
/// report that position rather than <see cref="Line"/> and <see cref="Column"/>.
/// </summary>
public sealed record GenerationError(string Code, string Message, int Line, int Column)
{
    public SourceSpan? Source { get; init; }
}
