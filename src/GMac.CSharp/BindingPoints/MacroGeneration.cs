using GMac.Dsl.Generation;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// Generates one macro for a set of bindings, after <see cref="BindingTextCheck"/> has found their C#
/// text fit to paste: <c>generate</c>, <c>verify</c> and <c>show</c> all go through here.
/// </summary>
internal static class MacroGeneration
{
    public static GenerationOutcome Generate(GenerationContext context, string macroName, IReadOnlyList<BindingSpec> specs, int regionLine, string filePath)
    {
        if (context.Project.Model.Macros.TryGetValue(macroName, out var macro) && BindingTextCheck.Check(macro, specs, filePath) is { Count: > 0 } errors)
            return new GenerationOutcome(null, errors, null);
        return context.Generator.Generate(macroName, specs, regionLine, filePath);
    }
}
