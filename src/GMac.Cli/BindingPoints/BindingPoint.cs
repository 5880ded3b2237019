using GMac.Dsl.Generation;

namespace GMac.Cli.BindingPoints;

/// <summary>
/// A <c>#region GMac : Macro</c> … <c>#endregion</c> block of a C# file. Lines are 0-based
/// indexes into the file's lines; <see cref="RegionLineNumber"/> is the 1-based line for messages.
/// </summary>
internal sealed record BindingPoint(string MacroName, int RegionLine, int EndRegionLine, string Indent, IReadOnlyList<BindingLine> Bindings)
{
    public int RegionLineNumber => RegionLine + 1;

    public IReadOnlyList<BindingSpec> Specs => Bindings.Select(b => b.Spec).ToList();
}
