using GMac.Dsl.Generation;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// A <c>#region GMac : Macro</c> … <c>#endregion</c> block of a C# file. Lines are 0-based
/// indexes into the file's lines; <see cref="RegionLineNumber"/> and <see cref="RegionColumn"/>
/// locate the <c>#region</c> for messages. <see cref="Scope"/> holds the names its temporaries must avoid,
/// <see cref="Placement"/> the locals its code must not declare again.
/// </summary>
internal sealed record BindingPoint(string MacroName, int RegionLine, int EndRegionLine, string Indent, IReadOnlyList<BindingLine> Bindings,
    int RegionColumn, RegionScope Scope)
{
    public int RegionLineNumber => RegionLine + 1;

    /// <summary>The line ending of the <c>#region</c> line, which the generated lines get.</summary>
    public string NewLine { get; init; } = "\n";

    public RegionPlacement Placement { get; init; } = RegionPlacement.Unknown;

    public IReadOnlyList<BindingSpec> Specs => Bindings.Select(b => b.Spec).ToList();
}
