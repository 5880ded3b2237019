using GMac.Dsl.Diagnostics;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// The result of regenerating one file: the new text (equal to the old when nothing changed or
/// anything failed), per-region outcomes, and every problem found.
/// </summary>
internal sealed record FileGeneration(BindingPointFile File, string NewText, IReadOnlyList<GeneratedRegion> Regions, IReadOnlyList<Diagnostic> Diagnostics)
{
    public bool Succeeded => Diagnostics.Count == 0;

    public bool Changed => Succeeded && !string.Equals(NewText, File.Source.Text, StringComparison.Ordinal);
}
