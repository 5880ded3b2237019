using ScottPlot;
using ScottPlot.TickGenerators;

namespace RayTracer.Cli.Experiments;

/// <summary>Grouped bar charts in the manner of thesis Figures 7-4 to 7-7: one group per scene, one bar per series.</summary>
internal static class InstancingCharts
{
    public const int Width = 1000;
    public const int Height = 480;

    private static readonly Color[] Colours =
    [
        new(31, 119, 180), new(255, 127, 14), new(214, 39, 40), new(44, 160, 44), new(148, 103, 189),
    ];

    /// <summary>A PNG of <paramref name="values"/>[series][group], labelled by <paramref name="groups"/> and <paramref name="series"/>.</summary>
    public static byte[] Grouped(string title, string axisLabel, IReadOnlyList<string> groups, IReadOnlyList<string> series,
        IReadOnlyList<IReadOnlyList<double>> values)
    {
        if (values.Count != series.Count || values.Any(v => v.Count != groups.Count))
            throw new ArgumentException("one value per series and group is needed", nameof(values));
        if (values.SelectMany(v => v).Any(v => !double.IsFinite(v)))
            throw new ArgumentException("every value must be finite", nameof(values));

        var plot = new Plot();
        var width = 0.8 / series.Count;
        var bars = new List<Bar>();
        for (var g = 0; g < groups.Count; g++)
            for (var s = 0; s < series.Count; s++)
                bars.Add(new Bar
                {
                    Position = g + (s - (series.Count - 1) / 2.0) * width,
                    Value = values[s][g],
                    FillColor = Colours[s % Colours.Length],
                    LineWidth = 0,
                    Size = width * 0.95,
                });
        plot.Add.Bars(bars);
        plot.Axes.Bottom.TickGenerator = new NumericManual(
            Enumerable.Range(0, groups.Count).Select(g => (double)g).ToArray(), [.. groups]);
        plot.Grid.XAxisStyle.MajorLineStyle.Width = 0;
        var low = Math.Min(0, values.SelectMany(v => v).Min());
        var high = Math.Max(0, values.SelectMany(v => v).Max());
        // All values zero: a unit range, so the axis is not degenerate (ScottPlot needs low < high).
        var margin = 0.08 * (high > low ? high - low : 1.0);
        plot.Axes.SetLimits(-0.6, groups.Count - 0.4, low < 0 ? low - margin : 0, high + margin);
        plot.YLabel(axisLabel);
        plot.Title(title);
        for (var s = 0; s < series.Count; s++)
            plot.Legend.ManualItems.Add(new LegendItem { LabelText = series[s], FillColor = Colours[s % Colours.Length] });
        plot.ShowLegend(Edge.Bottom);
        return plot.GetImageBytes(Width, Height, ImageFormat.Png);
    }
}
