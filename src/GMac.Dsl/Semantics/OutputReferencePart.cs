namespace GMac.Dsl.Semantics;

/// <summary>
/// A <c>&lt;mv.blade&gt;</c> reference of an output block; <see cref="Coefficient"/> is null when the
/// name or blade did not bind (the binder has reported it, so such a block is never generated).
/// </summary>
public sealed record OutputReferencePart(string Text, BoundCoefficient? Coefficient) : OutputPart(Text);
