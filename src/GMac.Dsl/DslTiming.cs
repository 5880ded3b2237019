using System.Diagnostics;
using SafeFiles;

namespace GMac.Dsl;

/// <summary>
/// Warm parse+bind time of a DSL folder: sources are read once, then parsed and
/// bound repeatedly; the median run is reported (benchmarks call this too).
/// </summary>
public static class DslTiming
{
    public static TimeSpan MeasureWarm(string directory, int repetitions)
    {
        var sources = SourceTree.List(directory, "*.gmac").Files
            .Select(p => (p, File.ReadAllText(p)))
            .ToList();
        DslProject.FromSources(sources); // warm-up: JIT and static tables
        var times = new List<TimeSpan>();
        for (var i = 0; i < Math.Max(1, repetitions); i++)
        {
            var watch = Stopwatch.StartNew();
            DslProject.FromSources(sources);
            times.Add(watch.Elapsed);
        }
        times.Sort();
        return times[times.Count / 2];
    }
}
