namespace GMac.Dsl.Generation;

/// <summary>
/// A quoted binding value: a scalar expression whose holes are host expressions
/// (<c>"2 * &lt;p.x&gt;"</c>), or for an output a single hole naming the target.
/// </summary>
/// <param name="Parts">The parts in order; when <paramref name="Problem"/> is set, those read before it.</param>
/// <param name="Target">The host's reading of the value as an output target (one hole and nothing else), or null.</param>
/// <param name="Problem">Why the text is no template (an unclosed hole), or null.</param>
public sealed record TemplateValue(string Text, IReadOnlyList<TemplatePart> Parts, string? Target, string? Problem = null) : BindingValue(Text)
{
    public override string? Target { get; } = Target;

    /// <summary>The holes, in order.</summary>
    public IEnumerable<HostExpression> Holes => Parts.OfType<TemplateHole>().Select(h => h.Expression);

    /// <summary>The one hole of a template that is nothing else (spaces aside), or null.</summary>
    public HostExpression? SingleHole =>
        Problem is null && Parts.Where(p => p is not ScalarTextPart { Text: var t } || !string.IsNullOrWhiteSpace(t)).ToList() is [TemplateHole only]
            ? only.Expression : null;
}
