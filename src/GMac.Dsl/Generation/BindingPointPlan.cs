using GMac.Core.CodeGeneration;
using GMac.Dsl.Semantics;

namespace GMac.Dsl.Generation;

/// <summary>
/// A binding point ready to generate: the request for the code generator, the target-language
/// text behind each input variable, and the macro run on doubles for the same bindings (the
/// reference <c>gmac verify</c> compares the generated code with).
/// </summary>
public sealed record BindingPointPlan(
    MacroSymbol Macro,
    CodeGenerationRequest Request,
    IReadOnlyDictionary<string, string> InputTexts,
    Func<IReadOnlyDictionary<string, double>, IReadOnlyDictionary<string, double>> NumericReference)
{
    /// <summary>
    /// No binding named an output, so every output coefficient is written to its default name
    /// (<c>y_e1</c>), which the emitted code declares.
    /// </summary>
    public bool DefaultOutputs { get; init; }
}
