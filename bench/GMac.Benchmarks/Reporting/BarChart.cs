using GMac.Benchmarks.Applications;

namespace GMac.Benchmarks.Reporting;

/// <summary>
/// Grouped bars in the manner of thesis Figure 7-2: per kernel (numbered as in the report) the
/// generated, direct and hand times per item, on a logarithmic axis labelled in ns at each decade.
/// </summary>
public static class BarChart
{
    public static readonly (byte R, byte G, byte B) GeneratedColour = (31, 119, 180);
    public static readonly (byte R, byte G, byte B) DirectColour = (214, 39, 40);
    public static readonly (byte R, byte G, byte B) HandColour = (44, 160, 44);

    private static readonly (byte, byte, byte) White = (255, 255, 255);
    private static readonly (byte, byte, byte) Grid = (220, 220, 220);
    private static readonly (byte, byte, byte) Ink = (40, 40, 40);

    public static byte[] Render(IReadOnlyList<KernelTiming> timings)
    {
        if (timings.Count == 0) throw new ArgumentException("nothing to draw", nameof(timings));
        const int bar = 12, gap = 18, left = 70, right = 20, top = 20, plotHeight = 360, bottom = 40, scale = 2;
        var group = 3 * bar + gap;
        var width = left + timings.Count * group + right;
        var height = top + plotHeight + bottom;
        var canvas = new Canvas(width, height, White);

        var values = timings.SelectMany(t => new[] { t.GeneratedNs, t.DirectNs, t.HandNs }).Where(v => v > 0).ToArray();
        var lo = Math.Floor(Math.Log10(values.Min()));
        var hi = Math.Max(lo + 1, Math.Ceiling(Math.Log10(values.Max())));
        int Y(double ns) => top + plotHeight - (int)Math.Round((Math.Log10(Math.Max(ns, Math.Pow(10, lo))) - lo) / (hi - lo) * plotHeight);

        for (var d = lo; d <= hi; d++)
        {
            var y = Y(Math.Pow(10, d));
            canvas.Fill(left, y, width - left - right, 1, Grid);
            if (d >= 0)
            {
                var label = (long)Math.Pow(10, d);
                canvas.Number(left - 8 - Canvas.NumberWidth(label, scale), y - 5, label, scale, Ink);
            }
        }
        canvas.Fill(left, top, 1, plotHeight + 1, Ink);
        canvas.Fill(left, top + plotHeight, width - left - right, 1, Ink);

        for (var k = 0; k < timings.Count; k++)
        {
            var x = left + gap / 2 + k * group;
            var t = timings[k];
            var bars = new[] { (t.GeneratedNs, GeneratedColour), (t.DirectNs, DirectColour), (t.HandNs, HandColour) };
            for (var b = 0; b < bars.Length; b++)
            {
                var y = Y(bars[b].Item1);
                canvas.Fill(x + b * bar, y, bar - 2, top + plotHeight - y, bars[b].Item2);
            }
            var number = k + 1;
            canvas.Number(x + (3 * bar - Canvas.NumberWidth(number, scale)) / 2, top + plotHeight + 10, number, scale, Ink);
        }
        return canvas.ToPng();
    }
}
