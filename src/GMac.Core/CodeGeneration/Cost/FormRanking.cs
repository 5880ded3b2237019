using GMac.Core.CodeGeneration.Accuracy;
using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Cost;

/// <summary>
/// Chooses among candidate forms of one computation: accuracy first (the
/// <see cref="AccuracyProbe"/> rule: a form whose error is far above the best form's drops out),
/// then the estimated time (<see cref="TimeModel"/>), then the weighted operation count, then
/// fewer temporaries. More operations are right when they shorten the chain that every output
/// waits for, as computing v2 − v1 first does in front of a division.
/// </summary>
public static class FormRanking
{
    /// <summary>The candidates' indices, best first.</summary>
    public static IReadOnlyList<int> Rank(IReadOnlyList<CodeBlock> candidates, SideRelations relations, OperationTimes? times = null, bool fusedMultiplyAdd = false)
    {
        ArgumentNullException.ThrowIfNull(candidates);
        ArgumentNullException.ThrowIfNull(relations);
        times ??= OperationTimes.Zen;
        var keys = candidates.Select((b, i) => (Index: i, Cycles: TimeModel.Estimate(b, times, fusedMultiplyAdd).Cycles, Stats: b.Statistics())).ToList();
        var byTime = keys.OrderBy(k => k.Cycles).ThenBy(k => k.Stats.Cost).ThenBy(k => k.Stats.Temporaries).ThenBy(k => k.Index).Select(k => k.Index).ToList();
        // the probe keeps the fastest unless it is far less accurate than another
        var chosen = byTime[AccuracyProbe.MostAccurateAffordable(byTime.Select(i => candidates[i]).ToList(), relations)];
        return [chosen, .. byTime.Where(i => i != chosen)];
    }
}
