using RayTracer.Geometry.Meshes;
using ScottPlot;
using ScottPlot.TickGenerators;

namespace RayTracer.Cli.Experiments;

/// <summary>The experiment's charts: times relative to Möller–Trumbore, and Figure 7-9's gain of Plücker over the algebraic test.</summary>
public static class TrianglesCharts
{
    public const int Width = 1000, Height = 480;

    private static readonly Color[] Colours = [new(31, 119, 180), new(214, 39, 40), new(44, 160, 44), new(148, 103, 189)];

    /// <summary>Per scene, each test's time over Möller–Trumbore's, for render and nearest-hit time side by side.</summary>
    public static byte[] RelativeTimes(IReadOnlyList<TrianglesMeasurement> results, Func<TrianglesMeasurement, TimeSpan> time, string what)
    {
        var scenes = results.Select(r => r.Scene).Distinct().ToArray();
        var tests = TrianglesExperiment.Tests;
        var plot = new Plot();
        const double barWidth = 0.2;
        var bars = new List<Bar>();
        for (var s = 0; s < scenes.Length; s++)
        {
            var baseline = time(Find(results, scenes[s], TriangleTest.MollerTrumbore)).TotalSeconds;
            for (var k = 0; k < tests.Count; k++)
            {
                var value = time(Find(results, scenes[s], tests[k])).TotalSeconds / baseline;
                bars.Add(new Bar
                {
                    Position = s + (k - 1.5) * barWidth,
                    Value = value,
                    FillColor = Colours[k],
                    LineWidth = 0,
                    Size = barWidth * 0.95,
                    Label = value.ToString("0.00", System.Globalization.CultureInfo.InvariantCulture),
                });
            }
        }

        var barPlot = plot.Add.Bars(bars);
        barPlot.ValueLabelStyle.FontSize = 10;
        var line = plot.Add.HorizontalLine(1.0);
        line.LineColor = new Color(0, 0, 0, 100);
        line.LinePattern = LinePattern.Dashed;
        plot.Axes.Bottom.TickGenerator = new NumericManual(Enumerable.Range(0, scenes.Length).Select(s => (double)s).ToArray(), scenes);
        var top = bars.Max(b => b.Value) * 1.15;
        plot.Axes.SetLimits(-0.6, scenes.Length - 0.4, 0, top);
        plot.Grid.XAxisStyle.MajorLineStyle.Width = 0;
        plot.YLabel($"{what} / Möller–Trumbore's");
        plot.Title($"Ray–triangle tests under the BIH: {what} relative to Möller–Trumbore (lower is faster)");
        for (var k = 0; k < tests.Count; k++)
            plot.Legend.ManualItems.Add(new LegendItem { LabelText = tests[k].Name(), FillColor = Colours[k] });
        plot.ShowLegend(Edge.Bottom);
        return plot.GetImageBytes(Width, Height, ImageFormat.Png);
    }

    /// <summary>Figure 7-9: (1 − P/A) in percent of render time, for both Plücker variants.</summary>
    public static byte[] PluckerGain(IReadOnlyList<TrianglesMeasurement> results)
    {
        var scenes = results.Select(r => r.Scene).Distinct().ToArray();
        TriangleTest[] variants = [TriangleTest.Plucker, TriangleTest.PluckerEdges];
        var plot = new Plot();
        const double barWidth = 0.35;
        var bars = new List<Bar>();
        for (var s = 0; s < scenes.Length; s++)
        {
            var algebraic = Find(results, scenes[s], TriangleTest.Algebraic).RenderCpuTime.TotalSeconds;
            for (var k = 0; k < variants.Length; k++)
            {
                var gain = 100 * (1 - Find(results, scenes[s], variants[k]).RenderCpuTime.TotalSeconds / algebraic);
                bars.Add(new Bar
                {
                    Position = s + (k - 0.5) * barWidth,
                    Value = gain,
                    FillColor = Colours[2 + k],
                    LineWidth = 0,
                    Size = barWidth * 0.95,
                    Label = gain.ToString("0.0", System.Globalization.CultureInfo.InvariantCulture) + "%",
                });
            }
        }

        var barPlot = plot.Add.Bars(bars);
        barPlot.ValueLabelStyle.FontSize = 10;
        plot.Axes.Bottom.TickGenerator = new NumericManual(Enumerable.Range(0, scenes.Length).Select(s => (double)s).ToArray(), scenes);
        var extent = Math.Max(5, bars.Max(b => Math.Abs(b.Value)) * 1.3);
        plot.Axes.SetLimits(-0.6, scenes.Length - 0.4, -extent, extent);
        plot.Grid.XAxisStyle.MajorLineStyle.Width = 0;
        plot.YLabel("gain over the algebraic test (%)");
        plot.Title("Figure 7-9 re-created: render CPU-time gain of the Plücker test over the algebraic test, (1 − P/A)");
        for (var k = 0; k < variants.Length; k++)
            plot.Legend.ManualItems.Add(new LegendItem { LabelText = variants[k].Name(), FillColor = Colours[2 + k] });
        plot.ShowLegend(Edge.Bottom);
        return plot.GetImageBytes(Width, Height, ImageFormat.Png);
    }

    internal static TrianglesMeasurement Find(IReadOnlyList<TrianglesMeasurement> results, string scene, TriangleTest test) =>
        results.First(r => r.Scene == scene && r.Test == test);
}
