namespace GMac.Dsl.Generation;

/// <summary>A piece of a <see cref="TemplateValue"/>: scalar-expression text or a host-expression hole.</summary>
public abstract record TemplatePart;
