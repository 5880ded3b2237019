using GMac.Benchmarks.Applications;
using ScottPlot;
using ScottPlot.TickGenerators;

namespace GMac.Benchmarks.Reporting;

/// <summary>
/// Grouped bars in the manner of thesis Figure 7-2: per kernel the generated, direct and hand
/// times per item, on a logarithmic axis in nanoseconds, with a legend and the kernels named.
/// </summary>
public static class BarChart
{
    public static readonly Color GeneratedColour = new(31, 119, 180);
    public static readonly Color DirectColour = new(214, 39, 40);
    public static readonly Color HandColour = new(44, 160, 44);

    public const int Width = 1200;
    public const int Height = 590;

    public static byte[] Render(IReadOnlyList<KernelTiming> timings)
    {
        if (timings.Count == 0) throw new ArgumentException("nothing to draw", nameof(timings));
        var values = timings.SelectMany(t => new[] { t.GeneratedNs, t.DirectNs, t.HandNs }).ToArray();
        if (values.Any(v => !(v > 0) || !double.IsFinite(v)))
            throw new ArgumentException("every time must be positive and finite to sit on a log axis", nameof(timings));

        // ScottPlot has no logarithmic axis: bars are drawn in log10 units from the decade below
        // the fastest item, and the ticks are labelled back in nanoseconds.
        var floor = Math.Floor(Math.Log10(values.Min()));
        var ceiling = Math.Ceiling(Math.Log10(values.Max()));
        var plot = new Plot();
        var series = new[]
        {
            (Label: "generated", Colour: GeneratedColour, Pick: (Func<KernelTiming, double>)(t => t.GeneratedNs)),
            (Label: "direct (Multivector<double>)", Colour: DirectColour, Pick: t => t.DirectNs),
            (Label: "hand-written", Colour: HandColour, Pick: t => t.HandNs),
        };
        const double barWidth = 0.27;
        var bars = new List<Bar>();
        for (var k = 0; k < timings.Count; k++)
            for (var s = 0; s < series.Length; s++)
                bars.Add(new Bar
                {
                    Position = k + (s - 1) * barWidth,
                    ValueBase = floor,
                    Value = Math.Log10(series[s].Pick(timings[k])),
                    FillColor = series[s].Colour,
                    LineWidth = 0,
                    Size = barWidth * 0.95,
                });
        plot.Add.Bars(bars);

        var decades = Enumerable.Range(0, (int)(ceiling - floor) + 1).Select(d => floor + d).ToArray();
        plot.Axes.Left.TickGenerator = new NumericManual(decades, decades.Select(DecadeLabel).ToArray());
        plot.Axes.Bottom.TickGenerator = new NumericManual(
            Enumerable.Range(0, timings.Count).Select(k => (double)k).ToArray(),
            timings.Select(t => t.Kernel).ToArray());
        plot.Axes.Bottom.TickLabelStyle.Rotation = -40;
        plot.Axes.Bottom.TickLabelStyle.Alignment = Alignment.MiddleRight;
        plot.Axes.Bottom.MinimumSize = 170; // room for the longest kernel name, rotated
        plot.Axes.SetLimits(-0.6, timings.Count - 0.4, floor, ceiling);
        plot.Grid.XAxisStyle.MajorLineStyle.Width = 0;

        plot.YLabel("time per item (ns, log scale)");
        plot.Title("GA applications: generated code against a direct GA implementation and hand-written formulas");
        foreach (var s in series)
            plot.Legend.ManualItems.Add(new LegendItem { LabelText = s.Label, FillColor = s.Colour });
        plot.ShowLegend(Edge.Bottom);
        return plot.GetImageBytes(Width, Height, ImageFormat.Png);
    }

    private static string DecadeLabel(double exponent) => exponent switch
    {
        >= 0 => Math.Pow(10, exponent).ToString("N0", System.Globalization.CultureInfo.InvariantCulture),
        _ => Math.Pow(10, exponent).ToString("0.###", System.Globalization.CultureInfo.InvariantCulture),
    };
}
