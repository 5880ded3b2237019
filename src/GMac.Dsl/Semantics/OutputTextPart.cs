namespace GMac.Dsl.Semantics;

/// <summary>Host-language text of an output block, copied to the generated code as it is.</summary>
public sealed record OutputTextPart(string Text) : OutputPart(Text);
