using System.Globalization;
using GMac.Benchmarks.Reporting;

namespace GMac.Benchmarks.Tests.Reporting;

public class KernelsCommand_Ratios
{
    [Fact]
    public void Ratio_mode_prints_one_parsable_line_per_kernel_whichever_variant_comes_first()
    {
        foreach (var handFirst in new[] { false, true })
        {
            var output = new StringWriter();
            string[] args = handFirst ? ["--ratio", "--hand-first", "--code-shift", "3", "Circ3"] : ["--ratio", "Circ3"];
            Assert.Equal(0, KernelsCommand.Run(args, output, new StringWriter()));
            var fields = Assert.Single(output.ToString().Split('\n', StringSplitOptions.RemoveEmptyEntries)).Split(' ');
            Assert.Equal([KernelsCommand.RatioLine, "Circ3"], fields[..2]);
            var (ratio, generatedNs, handNs) = (Parse(fields[2]), Parse(fields[3]), Parse(fields[4]));
            Assert.True(generatedNs > 0 && handNs > 0 && double.IsFinite(generatedNs) && double.IsFinite(handNs), output.ToString());
            Assert.True(ratio > 0 && double.IsFinite(ratio), output.ToString());
        }
    }

    [Fact]
    public void Unknown_kernels_and_options_are_refused_with_the_usage()
    {
        var error = new StringWriter();
        Assert.Equal(2, KernelsCommand.Run(["--ratio", "NoSuchKernel"], new StringWriter(), error));
        Assert.Contains("usage: GMac.Benchmarks kernels [--ratio] [--hand-first] [--code-shift N] NAME...", error.ToString());
        Assert.Equal(2, KernelsCommand.Run(["--fast", "Circ3"], new StringWriter(), new StringWriter()));
        foreach (var shift in new[] { new[] { "--code-shift", "Circ3" }, ["--code-shift", "-1", "Circ3"], ["Circ3", "--code-shift"] })
        {
            var message = new StringWriter();
            Assert.Equal(2, KernelsCommand.Run(["--ratio", .. shift], new StringWriter(), message));
            Assert.Contains("--code-shift takes a count of methods", message.ToString());
        }
    }

    [Fact]
    public void The_report_takes_the_median_of_ratios_timed_in_fresh_processes()
    {
        var (median, min, max) = new ProcessRatioTimer(processes: 1).GeneratedOverHand("Circ3");
        Assert.Equal(min, median);
        Assert.Equal(max, median);
        Assert.True(median > 0 && double.IsFinite(median));
    }

    private static double Parse(string s) => double.Parse(s, CultureInfo.InvariantCulture);
}
