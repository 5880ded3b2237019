using GMac.Core.CodeGeneration.Passes;

namespace GMac.Core.CodeGeneration;

/// <summary>
/// The blocks each pass is known to leave as they are, within one run of the optimizer. Every pass
/// is idempotent (run on its own output it changes nothing; <c>OptimizerPasses_Idempotence</c>
/// checks this on the library's blocks), so whatever a pass returns is one of its fixed points,
/// and a later round that hands the pass an equal block can skip it. Most passes change nothing
/// in the last rounds of the optimizer's loop, and those runs took more of its time than the runs
/// that did change something.
/// </summary>
internal sealed class PassFixedPoints
{
    private readonly Dictionary<(IOptimizerPass Pass, int Hash), List<CodeBlock>> _known = [];

    /// <summary>Whether <paramref name="pass"/> is known to return a block equal to <paramref name="block"/>.</summary>
    public bool Contains(IOptimizerPass pass, CodeBlock block) =>
        _known.TryGetValue((pass, block.StructureHash), out var blocks)
        && blocks.Exists(b => b.HasSameStatements(block));

    public void Add(IOptimizerPass pass, CodeBlock fixedPoint)
    {
        var key = (pass, fixedPoint.StructureHash);
        if (!_known.TryGetValue(key, out var blocks)) _known[key] = blocks = [];
        if (!blocks.Exists(b => ReferenceEquals(b, fixedPoint))) blocks.Add(fixedPoint);
    }
}
