using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary>A GA macro: typed inputs and outputs and its bound statements.</summary>
public sealed class MacroSymbol(string name, SourceSpan declaration) : Symbol(name, declaration)
{
    public IReadOnlyList<VariableSymbol> Inputs { get; internal set; } = [];
    public IReadOnlyList<VariableSymbol> Outputs { get; internal set; } = [];
    public IReadOnlyList<VariableSymbol> Temporaries { get; internal set; } = [];
    public IReadOnlyList<BoundStatement> Statements { get; internal set; } = [];

    /// <summary>Per statement, whether it can reach an output or the output text (see <see cref="Liveness"/>); empty: all can.</summary>
    internal bool[] LiveStatements { get; set; } = [];

    /// <summary>Macros this one calls, directly.</summary>
    public IReadOnlyList<MacroSymbol> Callees { get; internal set; } = [];
}
