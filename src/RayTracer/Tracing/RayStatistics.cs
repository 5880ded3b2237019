namespace RayTracer.Tracing;

/// <summary>Per-thread ray counters; the renderer sums the differences it sees around each tile.</summary>
public static class RayStatistics
{
    [ThreadStatic]
    private static long _primary;

    [ThreadStatic]
    private static long _total;

    public static void CountPrimary() => _primary++;

    /// <summary>Counts any ray cast into the scene (primary, secondary or shadow).</summary>
    public static void CountRay() => _total++;

    /// <summary>The calling thread's (primary, total) counts so far.</summary>
    public static (long Primary, long Total) Snapshot() => (_primary, _total);
}
