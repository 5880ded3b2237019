namespace GMac.Benchmarks.Generation;

/// <summary>Time to generate one macro with its default bindings: cold (fresh project, generator and empty cache) and warm (same generator again).</summary>
public sealed record MacroGenerationTiming(string Macro, double ColdMs, double WarmMs, string? Error);
