namespace GMac.Dsl.Generation;

/// <summary>A binding-point problem, at the line of the binding that caused it (or the region's first line).</summary>
public sealed record GenerationError(string Code, string Message, int Line, int Column);
