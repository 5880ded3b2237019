using GMac.Dsl.Generation;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// One binding point after generation: its outcome and, when it succeeded, the emitted C# body in
/// <see cref="ScalarType"/> (its <c>//GMac.Type</c> line's, else the run's).
/// </summary>
internal sealed record GeneratedRegion(BindingPoint Point, GenerationOutcome? Outcome, string? Code)
{
    public string ScalarType { get; init; } = "double";

    /// <summary>Whether the code fuses products into sums (its <c>//GMac.Fma</c> line's, else the run's).</summary>
    public bool FusedMultiplyAdd { get; init; }
}
