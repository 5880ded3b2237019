using GMac.Dsl.Diagnostics;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// A C# file split into lines (each with its own line break) with the binding points found in
/// it, the problems found while reading them, and the identifiers of its bind lines (which no
/// temporary of the file may take, whatever scope they come from), and the namespaces its
/// <c>using</c> directives import (which decides whether vector code can name <c>Vector256</c> unqualified).
/// </summary>
internal sealed record BindingPointFile(
    SourceText Source,
    IReadOnlyList<string> Lines,
    IReadOnlyList<BindingPoint> Points,
    IReadOnlyList<Diagnostic> Diagnostics,
    IReadOnlySet<string> Identifiers,
    IReadOnlySet<string> ImportedNamespaces)
{
    public string Path => Source.Path;
}
