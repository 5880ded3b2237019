namespace GMac.Benchmarks.Generation;

/// <summary>The generation suite: per macro, and the whole library at once.</summary>
public sealed record GenerationTimings(
    IReadOnlyList<MacroGenerationTiming> Macros,
    double FirstPassMs,
    double LoadMs,
    IReadOnlyList<double> LibraryColdRuns,
    double LibraryWarmMs,
    IReadOnlyList<double> LibraryParallelColdRuns)
{
    /// <summary>The untimed passes after the first, until the JIT compiled no new method.</summary>
    public double SettlingMs { get; init; }

    /// <summary>The median of the cold runs of the whole library.</summary>
    public double LibraryColdMs => GenerationTimer.Median(LibraryColdRuns);

    /// <summary>The median of the cold runs with the macros shared out over every core.</summary>
    public double LibraryParallelColdMs => GenerationTimer.Median(LibraryParallelColdRuns);
}
