using GMac.CSharp.Emit;
using GMac.Dsl.Diagnostics;
using GMac.Dsl.Generation;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// Generates one macro for a set of bindings, after <see cref="BindingTextCheck"/> has found their C#
/// text fit to paste, and prints it: <c>generate</c>, <c>verify</c> and <c>show</c> all go through here,
/// one way (host → Dsl → Core, back to the host's emitter).
/// </summary>
internal static class MacroGeneration
{
    /// <summary>
    /// Generates and prints: the outcome, and its code, or why a block that generated has no code
    /// (a constant out of the scalar type's range; an emitter defect), for the caller to report at its position.
    /// </summary>
    /// <param name="options">The printing choices, which may depend on the outcome (default outputs, aliasing).</param>
    /// <param name="batchIndex">The index of a <c>//GMac.Batch</c> line: the code is a loop over spans read at it.</param>
    public static (GenerationOutcome Outcome, string? Code, (DiagnosticDescriptor Descriptor, string Message)? Problem) GenerateCode(GenerationContext context,
        string macroName, IReadOnlyList<BindingSpec> specs, int regionLine, string filePath, Func<GenerationOutcome, CSharpEmitOptions> options,
        string? batchIndex = null)
    {
        var outcome = Generate(context, macroName, specs, regionLine, filePath);
        if (!outcome.Succeeded) return (outcome, null, null);
        var printing = options(outcome);
        if (CSharpEmitter.ConstantOutOfRange(outcome.Result!.Block, printing.ScalarType) is { } range)
            return (outcome, null, (DiagnosticCodes.ConstantOutOfRange, $"macro '{macroName}' cannot be generated in {printing.ScalarType}: {range}"));
        try
        {
            if (batchIndex is not null)
            {
                var (batch, batchProblem) = CSharpBatchEmitter.Emit(outcome.Result.Block, batchIndex, macroName, printing);
                return (outcome, batch, batchProblem is null ? null : (DiagnosticCodes.InvalidBatch, batchProblem));
            }
            return (outcome, CSharpEmitter.Emit(outcome.Result.Block, printing), null);
        }
        catch (InvalidOperationException e)
        {
            return (outcome, null, (DiagnosticCodes.InternalError, $"cannot print the code of macro '{macroName}': {e.Message}"));
        }
    }

    public static GenerationOutcome Generate(GenerationContext context, string macroName, IReadOnlyList<BindingSpec> specs, int regionLine, string filePath)
    {
        if (context.Project.Model.Macros.TryGetValue(macroName, out var macro) && BindingTextCheck.Check(macro, specs, filePath) is { Count: > 0 } errors)
            return new GenerationOutcome(null, errors, null);
        return context.Generator.Generate(macroName, specs, regionLine, filePath);
    }
}
