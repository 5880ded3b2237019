namespace GMac.Benchmarks.Generation;

/// <summary>The generation suite: per macro, and the whole library at once.</summary>
public sealed record GenerationTimings(
    IReadOnlyList<MacroGenerationTiming> Macros,
    double FirstPassMs,
    double LoadMs,
    double LibraryColdMs,
    double LibraryWarmMs);
