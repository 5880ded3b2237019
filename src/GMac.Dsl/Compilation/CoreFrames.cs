using GMac.Core.Algebra;
using GMac.Dsl.Semantics;

namespace GMac.Dsl.Compilation;

/// <summary>The algebra's <see cref="Frame"/> for each DSL frame, built once per model.</summary>
public sealed class CoreFrames
{
    private readonly Dictionary<FrameSymbol, Frame> _frames = [];

    public Frame this[FrameSymbol symbol]
    {
        get
        {
            lock (_frames)
            {
                if (!_frames.TryGetValue(symbol, out var frame))
                {
                    frame = new Frame(symbol.Name, symbol.BasisNames, Metric.FromMatrix(symbol.InnerProductMatrix, symbol.Name));
                    _frames[symbol] = frame;
                }
                return frame;
            }
        }
    }
}
