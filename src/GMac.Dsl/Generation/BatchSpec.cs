namespace GMac.Dsl.Generation;

/// <summary>
/// <c>//GMac.Batch("i");</c>: the binding point's code runs once per item of spans read and
/// written at <see cref="Index"/> (structure of arrays); the C# host writes the loop.
/// </summary>
public sealed record BatchSpec(string Index, int Line, int Column) : BindingSpec(Line, Column);
