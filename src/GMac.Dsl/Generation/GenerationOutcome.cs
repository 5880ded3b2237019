using GMac.Core.CodeGeneration;
using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Generation;

/// <summary>The generated statements of one binding point, or why there are none.</summary>
public sealed record GenerationOutcome(CodeGenerationResult? Result, IReadOnlyList<Diagnostic> Errors, BindingPointPlan? Plan)
{
    public bool Succeeded => Result is not null && Errors.Count == 0;
}
