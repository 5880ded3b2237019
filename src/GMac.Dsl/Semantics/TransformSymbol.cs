using GMac.Core.Numerics;
using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary>
/// A fixed linear transform between two frames of equal dimension, given as the
/// outermorphism of a vector map. <see cref="VectorMatrix"/> column j is the
/// image of source basis vector j in destination coordinates.
/// </summary>
public sealed class TransformSymbol(string name, SourceSpan declaration) : Symbol(name, declaration)
{
    public FrameSymbol Source { get; internal set; } = null!;
    public FrameSymbol Destination { get; internal set; } = null!;
    public TransformKind Kind { get; internal set; }
    public TransformSymbol? BasedOn { get; internal set; }
    public RationalMatrix? VectorMatrix { get; internal set; }
}
