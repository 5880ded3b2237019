using GMac.Dsl.Generation;

namespace GMac.Cli.BindingPoints;

/// <summary>One binding point after generation: its outcome and, when it succeeded, the emitted C# body.</summary>
internal sealed record GeneratedRegion(BindingPoint Point, GenerationOutcome? Outcome, string? Code);
