using GMac.Benchmarks.Applications;
using GMac.Benchmarks.Reporting;
using StbImageSharp;

namespace GMac.Benchmarks.Tests.Reporting;

public class BarChart_Rendering
{
    private static readonly KernelTiming[] Timings =
    [
        new("Alpha", 3.0, 2_000.0, 2.5),
        new("Beta", 0.8, 900.0, 1.1),
        new("Gamma", 40.0, 15_000.0, 35.0),
    ];

    [Fact]
    public void The_chart_decodes_as_a_png_of_the_stated_size()
    {
        var image = ImageResult.FromMemory(BarChart.Render(Timings), ColorComponents.RedGreenBlue);
        Assert.Equal(BarChart.Width, image.Width);
        Assert.Equal(BarChart.Height, image.Height);
    }

    [Fact]
    public void Each_series_is_drawn_in_its_colour_with_taller_bars_for_slower_items()
    {
        var image = ImageResult.FromMemory(BarChart.Render(Timings), ColorComponents.RedGreenBlue);
        var generated = PixelsOf(image, BarChart.GeneratedColour);
        var direct = PixelsOf(image, BarChart.DirectColour);
        var hand = PixelsOf(image, BarChart.HandColour);
        Assert.True(generated > 0 && direct > 0 && hand > 0, $"generated {generated}, direct {direct}, hand {hand} pixels");
        // Direct times are two to three decades above the others, so on a log axis its bars cover the most area.
        Assert.True(direct > 2 * generated, $"direct {direct} vs generated {generated}");
        Assert.True(direct > 2 * hand, $"direct {direct} vs hand {hand}");
    }

    [Theory]
    [InlineData(0.0)]
    [InlineData(-1.0)]
    [InlineData(double.NaN)]
    [InlineData(double.PositiveInfinity)]
    public void Times_that_cannot_sit_on_a_log_axis_are_refused(double bad)
    {
        Assert.Throws<ArgumentException>(() => BarChart.Render([new KernelTiming("Alpha", bad, 1.0, 1.0)]));
        Assert.Throws<ArgumentException>(() => BarChart.Render([]));
    }

    private static int PixelsOf(ImageResult image, ScottPlot.Color colour)
    {
        var count = 0;
        for (var i = 0; i < image.Data.Length; i += 3)
            if (image.Data[i] == colour.R && image.Data[i + 1] == colour.G && image.Data[i + 2] == colour.B)
                count++;
        return count;
    }
}
