using System.Runtime.CompilerServices;
using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Accuracy;

/// <summary>
/// A cheap measure of how much accuracy a code block loses: its outputs in doubles against the
/// same block evaluated exactly, on a few inputs that all sit near a large common value. Points
/// far from the origin and close together are where an expanded product of differences loses
/// everything, and where a form that subtracts the inputs first loses nothing; forms of the same
/// kernel that round alike come out within a small factor of each other. Inputs under a side
/// relation (the unit norm of a rotor) are drawn on it instead: a form reduced by the relation is
/// the same function as the others only there, and far off it (coefficients near 1e4 where their
/// squares sum to 1) it may cancel badly or not depending on the signs of the bound coefficients.
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
    public static double? Error(CodeBlock block) => Error(block, SideRelations.None);

    /// <summary>
    /// Errors already probed, per block (blocks are immutable): generation probes its forms once to
    /// decide on difference forms and again to rank them, and the exact evaluation is the costly part.
    /// </summary>
    private static readonly ConditionalWeakTable<CodeBlock, Tuple<SideRelations, double?>> Probed = new();

    /// <summary>As <see cref="Error(CodeBlock)"/>, with the inputs satisfying <paramref name="relations"/>.</summary>
    public static double? Error(CodeBlock block, SideRelations relations)
    {
        ArgumentNullException.ThrowIfNull(relations);
        if (Probed.TryGetValue(block, out var known) && ReferenceEquals(known.Item1, relations)) return known.Item2;
        var error = Probe(block, relations);
        Probed.AddOrUpdate(block, Tuple.Create(relations, error));
        return error;
    }

    private static double? Probe(CodeBlock block, SideRelations relations)
    {
        if (block.Statements.SelectMany(s => s.Expressions).SelectMany(e => e.DescendantsAndSelf()).Any(e => e is CallExpr)) return null;
        var names = block.InputText.Keys.ToArray();
        var worst = 0.0;
        for (var probe = 0; probe < Probes; probe++)
        {
            var doubles = new Dictionary<string, double>(StringComparer.Ordinal);
            for (var i = 0; i < names.Length; i++) doubles[names[i]] = Offset + Spread(probe, i);
            OntoRelations(doubles, relations, probe);
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
    public static int MostAccurateAffordable(IReadOnlyList<CodeBlock> candidatesCheapestFirst) =>
        MostAccurateAffordable(candidatesCheapestFirst, SideRelations.None);

    /// <summary>As <see cref="MostAccurateAffordable(IReadOnlyList{CodeBlock})"/>, probing on inputs that satisfy <paramref name="relations"/>.</summary>
    public static int MostAccurateAffordable(IReadOnlyList<CodeBlock> candidatesCheapestFirst, SideRelations relations)
    {
        ArgumentNullException.ThrowIfNull(relations);
        if (candidatesCheapestFirst.Count < 2) return 0;
        // forms that came out the same share one block, which Error probes once
        double? ErrorOf(CodeBlock b) => Error(b, relations);
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

    /// <summary>
    /// Moves the inputs of every relation v^p = P (v an input, P free of v) onto it: P's variables
    /// get small values (a unit rotor's coefficients lie in [−1, 1]), shrunk until an even root of
    /// P exists, and v its root. Variables an earlier relation set are kept, so relations that
    /// share variables do not undo each other; a relation with no real solution leaves its inputs as they were.
    /// </summary>
    private static void OntoRelations(Dictionary<string, double> values, SideRelations relations, int probe)
    {
        var fixedNames = new HashSet<string>(StringComparer.Ordinal);
        foreach (var rule in relations.Rules)
        {
            if (rule.Pattern.FactorArray is not [{ Atom: { Kind: AtomKind.Variable } atom, Power: var power }] ||
                !values.ContainsKey(atom.Name) || fixedNames.Contains(atom.Name) || rule.Replacement.Variables.Contains(atom.Name))
                continue;
            var free = rule.Replacement.Variables.Where(n => !fixedNames.Contains(n)).Order(StringComparer.Ordinal).ToArray();
            var trial = new Dictionary<string, double>(values, StringComparer.Ordinal);
            var scale = 1 / Math.Sqrt(free.Length + 1);
            for (var attempt = 0; attempt < 16; attempt++, scale /= 2)
            {
                foreach (var name in free) trial[name] = scale * Spread(probe, StableHash.Of(name));
                var p = rule.Replacement.Evaluate(n => trial.TryGetValue(n, out var v) ? v : 0);
                if (power % 2 == 0 && !(p > 0) || !double.IsFinite(p)) continue;
                var root = Math.Pow(Math.Abs(p), 1.0 / power);
                // an even root's sign is free: the probe picks it, so that both signs get tried
                trial[atom.Name] = p < 0 || power % 2 == 0 && Spread(probe, StableHash.Of(atom.Name)) < 0 ? -root : root;
                foreach (var name in free.Append(atom.Name))
                {
                    fixedNames.Add(name);
                    if (values.ContainsKey(name)) values[name] = trial[name];
                }
                break;
            }
        }
    }

    /// <summary>A deterministic value in [−1, 1) per probe and input, so generation stays reproducible.</summary>
    private static double Spread(int probe, int input)
    {
        var h = StableHash.Combine(StableHash.Combine(17, probe), input);
        return (h & 0xFFFF) / 32768.0 - 1;
    }
}
