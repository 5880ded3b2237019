using System.Diagnostics;

namespace GMac.Dsl;

/// <summary>
/// Warm parse+bind time of a loaded DSL project: its sources, already read, are parsed and bound
/// again repeatedly; the median run is reported (benchmarks call this too).
/// </summary>
public static class DslTiming
{
    public static TimeSpan MeasureWarm(DslProject project, int repetitions)
    {
        var sources = project.SyntaxTrees.Select(t => (t.FilePath, t.Text)).ToList();
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
