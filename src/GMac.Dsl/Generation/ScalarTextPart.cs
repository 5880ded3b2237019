namespace GMac.Dsl.Generation;

/// <summary>Text of a template's scalar expression (numbers, operators, functions) around its holes.</summary>
public sealed record ScalarTextPart(string Text) : TemplatePart;
