namespace GMac.Dsl.Semantics;

/// <summary>
/// A piece of an <c>output { … }</c> block, read once by the binder: host-language text copied as it
/// is, or a <c>&lt;mv.blade&gt;</c> reference whose value the generated code puts in its place.
/// </summary>
/// <param name="Text">The piece as written in the block (a reference with its brackets).</param>
public abstract record OutputPart(string Text);
