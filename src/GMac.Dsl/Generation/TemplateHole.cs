namespace GMac.Dsl.Generation;

/// <summary>A host expression inside a template, an atom of its scalar expression.</summary>
public sealed record TemplateHole(HostExpression Expression) : TemplatePart;
