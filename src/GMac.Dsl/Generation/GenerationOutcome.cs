using GMac.Core.CodeGeneration;

namespace GMac.Dsl.Generation;

/// <summary>The generated statements of one binding point, or why there are none.</summary>
public sealed record GenerationOutcome(CodeGenerationResult? Result, IReadOnlyList<GenerationError> Errors, BindingPointPlan? Plan)
{
    public bool Succeeded => Result is not null && Errors.Count == 0;
}
