namespace GMac.Dsl.Generation;

/// <summary>
/// The value side of a coefficient binding, read once by the host layer from its host-language
/// text: a number, a bare host expression, or a template (a scalar expression over host-expression
/// holes). The generator builds its scalar from this form and never reads the text itself.
/// </summary>
/// <param name="Text">The value as written, for messages.</param>
public abstract record BindingValue(string Text)
{
    /// <summary>The host expression an output coefficient is written to, or null when the value names none.</summary>
    public abstract string? Target { get; }
}
