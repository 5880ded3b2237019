using System.Diagnostics;

namespace GMac.Core.CodeGeneration;

/// <summary>
/// Where generation spends its time: inclusive time, bytes allocated and call count per stage and
/// per optimizer pass, gathered only while <see cref="Enabled"/> is set (the benchmark's
/// <c>generation --profile</c>), so ordinary runs pay one flag test per stage.
/// </summary>
public static class GenerationProfile
{
    private static readonly Dictionary<string, StageTotals> Totals = new(StringComparer.Ordinal);

    public static bool Enabled { get; set; }

    /// <summary>Milliseconds on some clock; wall time unless the caller supplies one that ignores other processes (thread CPU time).</summary>
    public static Func<double> Clock { get; set; } = () => Stopwatch.GetTimestamp() * 1000.0 / Stopwatch.Frequency;

    public readonly record struct StageTotals(double Ms, long Bytes, int Calls);

    public static IReadOnlyDictionary<string, StageTotals> Snapshot()
    {
        lock (Totals) return new Dictionary<string, StageTotals>(Totals, StringComparer.Ordinal);
    }

    public static void Reset()
    {
        lock (Totals) Totals.Clear();
    }

    public static T Time<T>(string stage, Func<T> work)
    {
        if (!Enabled) return work();
        var start = Clock();
        var bytes = GC.GetAllocatedBytesForCurrentThread();
        try
        {
            return work();
        }
        finally
        {
            var ms = Clock() - start;
            var allocated = GC.GetAllocatedBytesForCurrentThread() - bytes;
            lock (Totals)
            {
                var t = Totals.GetValueOrDefault(stage);
                Totals[stage] = new StageTotals(t.Ms + ms, t.Bytes + allocated, t.Calls + 1);
            }
        }
    }
}
