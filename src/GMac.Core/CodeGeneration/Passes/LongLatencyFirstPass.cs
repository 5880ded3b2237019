namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Moves each division, square root or other call, with the statements it needs, as early as they
/// can go; every other statement keeps its place relative to the rest. A division takes four times
/// as long as a multiplication: started first, its wait is filled by the work that does not lead to
/// it, where reached late it leaves the statements after it waiting. The JIT keeps the order of
/// statements and a processor reorders only within a window, so the order shows in time: the
/// skew-lines kernel ran 3–4 % faster with its division first, and as much again with the
/// denominator of its two quotients first. Blocks without such an operation
/// keep their order (moving stores or loads in them was measured slower as often as faster).
/// Changes no operation and no value.
/// </summary>
public sealed class LongLatencyFirstPass : IOptimizerPass
{
    public string Name => "long latency first";

    public CodeBlock Run(CodeBlock block)
    {
        var statements = block.Statements;
        if (statements.Count < 3 || BlockRewriting.Dependencies(block) is not var (assignments, reads)) return block;
        var definedAt = new Dictionary<string, int>(StringComparer.Ordinal);
        for (var i = 0; i < assignments.Length; i++) definedAt[assignments[i].Target] = i;

        // Long statements and everything they need, found from the last statement back. A
        // quotient x / d of two computed values (not a reciprocal) moves only the statements its
        // denominator needs: with both in source order the skew-lines kernel, which divides its
        // two numerators by |n|², measured 1.07 of hand time; with |n|² first, 1.04.
        var early = new bool[assignments.Length];
        for (var i = assignments.Length - 1; i >= 0; i--)
        {
            var value = assignments[i].Value;
            if (!early[i] && value is QuotientExpr { Numerator: not ConstantExpr } q && !IsLong(q.Numerator) && !IsLong(q.Denominator))
            {
                foreach (var v in q.Denominator.DescendantsAndSelf().OfType<VariableExpr>())
                    if (definedAt.TryGetValue(v.Name, out var d)) early[d] = true;
                continue;
            }
            if (!early[i] && !IsLong(value)) continue;
            early[i] = true;
            foreach (var d in reads[i]) early[d] = true;
        }
        if (!early.Contains(true)) return block;
        var order = assignments.Where((_, i) => early[i]).Concat(assignments.Where((_, i) => !early[i])).ToList<CodeStatement>();
        return order.SequenceEqual(statements) ? block : block.WithStatements(order);
    }

    private static bool IsLong(Expr e) => e.DescendantsAndSelf().Any(x => x is QuotientExpr or CallExpr or PowerExpr { Exponent: < 0 });
}
