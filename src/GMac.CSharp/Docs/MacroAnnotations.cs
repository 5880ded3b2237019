using GMac.Dsl.Diagnostics;

namespace GMac.CSharp.Docs;

/// <summary>The cookbook's reading of the comments above one macro.</summary>
internal sealed record MacroAnnotations(string Description, string? Hand, string? Group, IReadOnlyList<(string Parameter, string Binding, SourceSpan At)> Bind);
