using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary>A named definition of a GMacDSL project.</summary>
public abstract class Symbol(string name, SourceSpan declaration)
{
    public string Name { get; } = name;
    public SourceSpan Declaration { get; } = declaration;

    /// <summary>Set by the binder when anything refers to the symbol.</summary>
    public bool IsReferenced { get; internal set; }

    public override string ToString() => Name;
}
