namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Orders statements so that each one follows, as closely as its other inputs allow, the
/// statement it reads last: of the statements whose inputs are all computed, the next is the one
/// whose latest input was computed most recently (ties in the original order). A block that
/// computes all its differences first and their squares later becomes, per point, its
/// differences and then their square, as a hand derivation writes it; the processor, which
/// reorders only within a window, then finds multiplications among the subtractions from the
/// start. Measured on the sphere through four points moved to the origin
/// (<see cref="OriginShift"/>): 1.07 of the hand code's time in the first order, 1.035 in this one.
/// Changes no operation and no value.
/// </summary>
internal static class ConsumerFirstOrder
{
    public static CodeBlock Apply(CodeBlock block)
    {
        if (BlockRewriting.Dependencies(block) is not var (statements, reads)) return block;

        var emittedAt = new int[statements.Length];
        Array.Fill(emittedAt, -1);
        var order = new List<CodeStatement>(statements.Length);
        while (order.Count < statements.Length)
        {
            var best = -1;
            var bestLatest = int.MinValue;
            for (var i = 0; i < statements.Length; i++)
            {
                if (emittedAt[i] >= 0 || reads[i].Any(d => emittedAt[d] < 0)) continue;
                var latest = reads[i].Length == 0 ? -1 : reads[i].Max(d => emittedAt[d]);
                if (latest > bestLatest) (best, bestLatest) = (i, latest);
            }
            emittedAt[best] = order.Count;
            order.Add(statements[best]);
        }
        return order.SequenceEqual(block.Statements) ? block : block.WithStatements(order);
    }
}
