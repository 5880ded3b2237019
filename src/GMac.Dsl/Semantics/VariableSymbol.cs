using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary>A multivector of a macro: an input, an output or a temporary.</summary>
public sealed class VariableSymbol(string name, SourceSpan declaration, VariableKind kind) : Symbol(name, declaration)
{
    public VariableKind Kind { get; } = kind;

    /// <summary>Declared class of inputs and outputs; null for temporaries.</summary>
    public MultivectorClassSymbol? Class { get; internal set; }

    /// <summary>Frame of the value; null for a temporary holding a plain scalar.</summary>
    public FrameSymbol? Frame { get; internal set; }
}
