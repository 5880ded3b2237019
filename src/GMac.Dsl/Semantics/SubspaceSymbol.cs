using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary>A set of basis blades of one frame, each a bit mask of basis vectors.</summary>
public sealed class SubspaceSymbol(string name, SourceSpan declaration, FrameSymbol frame) : Symbol(name, declaration)
{
    public FrameSymbol Frame { get; } = frame;
    public IReadOnlyList<int> Blades { get; internal set; } = [];
}
