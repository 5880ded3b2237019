using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary>
/// Target-language text copied to the generated code, read once into its parts.
/// <see cref="TextStart"/> is where the text inside the braces begins, so a host that checks the
/// text can report a position in it.
/// </summary>
public sealed record BoundOutputStatement(IReadOnlyList<OutputPart> Parts, SourceSpan TextStart, SourceSpan Span)
    : BoundStatement(Span)
{
    /// <summary>The text inside the braces, as written.</summary>
    public string Text => string.Concat(Parts.Select(p => p.Text));

    /// <summary>The coefficients the text reads, in order.</summary>
    public IEnumerable<BoundCoefficient> References => Parts.OfType<OutputReferencePart>().Select(p => p.Coefficient).OfType<BoundCoefficient>();
}
