using GMac.Core.Numerics;

namespace GMac.Core.CodeGeneration.Accuracy;

/// <summary>
/// A cheap measure of how much accuracy a code block loses: its outputs in doubles against the
/// same block evaluated exactly, on a few inputs that all sit near a large common value. Points
/// far from the origin and close together are where an expanded product of differences loses
/// everything, and where a form that subtracts the inputs first loses nothing; forms of the same
/// kernel that round alike come out within a small factor of each other.
/// </summary>
public static class AccuracyProbe
{
    /// <summary>The common value of the probe inputs.</summary>
    public const double Offset = 1e4;

    /// <summary>A candidate counts as less accurate when its error exceeds the best candidate's by this factor...</summary>
    public const double Factor = 1000;

    /// <summary>...and this absolute level (relative to its outputs' size).</summary>
    public const double Threshold = 1e-10;

    private const int Probes = 3;

    /// <summary>The worst normwise relative error of the outputs over the probes; null where the block cannot be evaluated exactly (math calls, verbatim text, a zero division).</summary>
    public static double? Error(CodeBlock block)
    {
        if (block.Statements.SelectMany(s => s.Expressions).SelectMany(e => e.DescendantsAndSelf()).Any(e => e is CallExpr)) return null;
        var names = block.InputText.Keys.ToArray();
        var worst = 0.0;
        for (var probe = 0; probe < Probes; probe++)
        {
            var doubles = new Dictionary<string, double>(StringComparer.Ordinal);
            for (var i = 0; i < names.Length; i++) doubles[names[i]] = Offset + Spread(probe, i);
            var exact = ExactEvaluator.Evaluate(block, doubles.ToDictionary(kv => kv.Key, kv => Rational.FromDouble(kv.Value), StringComparer.Ordinal));
            if (exact is null || exact.Count == 0) return null;
            var computed = block.Evaluate(doubles);
            var largest = exact.Values.Max(v => Math.Abs(v.ToDouble()));
            if (largest == 0) continue;
            foreach (var (name, value) in exact)
            {
                var c = computed[name];
                if (!double.IsFinite(c)) return double.PositiveInfinity;
                worst = Math.Max(worst, Math.Abs((Rational.FromDouble(c) - value).ToDouble()) / largest);
            }
        }
        return worst;
    }

    /// <summary>
    /// Among candidates listed cheapest first, the index of the first whose error is not far above
    /// the best error of them all: accuracy overrules cost only when the cheaper form is clearly worse.
    /// </summary>
    public static int MostAccurateAffordable(IReadOnlyList<CodeBlock> candidatesCheapestFirst)
    {
        if (candidatesCheapestFirst.Count < 2) return 0;
        // forms that came out the same share one block: probe it once
        var probed = new Dictionary<CodeBlock, double?>(ReferenceEqualityComparer.Instance);
        double? ErrorOf(CodeBlock b) => probed.TryGetValue(b, out var e) ? e : probed[b] = Error(b);
        // The cheapest stays when it cannot be judged or is within the absolute level: the limit
        // is never below that level, so the others need not be probed.
        if (ErrorOf(candidatesCheapestFirst[0]) is not { } cheapest || cheapest <= Threshold) return 0;
        var errors = candidatesCheapestFirst.Select(ErrorOf).ToArray();
        var known = errors.Where(e => e is not null).Select(e => e!.Value).ToArray();
        if (known.Length < 2) return 0;
        var limit = Math.Max(Threshold, Factor * known.Min());
        for (var i = 0; i < errors.Length; i++)
            if (errors[i] is not { } e || e <= limit) return i;
        return 0;
    }

    /// <summary>A deterministic value in [−1, 1) per probe and input, so generation stays reproducible.</summary>
    private static double Spread(int probe, int input)
    {
        var h = StableHash.Combine(StableHash.Combine(17, probe), input);
        return (h & 0xFFFF) / 32768.0 - 1;
    }
}
