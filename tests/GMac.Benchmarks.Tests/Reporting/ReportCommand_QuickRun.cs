using GMac.Benchmarks.Kernels;
using GMac.Benchmarks.Reporting;
using GMac.Benchmarks.Tests.Support;

namespace GMac.Benchmarks.Tests.Reporting;

public class ReportCommand_QuickRun
{
    [Fact]
    public void Quick_report_writes_a_table_row_per_kernel_and_a_png()
    {
        var folder = Directory.CreateTempSubdirectory("gmac-bench-report-").FullName;
        try
        {
            var output = new StringWriter();
            var error = new StringWriter();
            var code = ReportCommand.Run(["--quick", "--no-generation", "--out", folder, "--dsl", RepositoryPaths.Dsl], output, error);

            Assert.True(code == 0, error.ToString());
            var markdown = File.ReadAllLines(Path.Combine(folder, ReportCommand.MarkdownFile));
            Assert.StartsWith("# ", markdown[0]);
            var header = Array.FindIndex(markdown, l => l.StartsWith("| # | kernel", StringComparison.Ordinal));
            Assert.True(header > 0);
            var columns = markdown[header].Split('|').Length;
            for (var i = 0; i < KernelCatalog.Names.Count; i++)
            {
                var row = markdown[header + 2 + i];
                Assert.Equal(columns, row.Split('|').Length);
                Assert.Contains($"| {KernelCatalog.Names[i]} |", row);
            }
            Assert.Contains(markdown, l => l.StartsWith("## Goals", StringComparison.Ordinal));
            var vector = Array.FindIndex(markdown, l => l.StartsWith("| kernel | scalar ns | Vector256 ns", StringComparison.Ordinal));
            Assert.True(vector > header, "no vector table");
            for (var i = 0; i < KernelCatalog.Names.Count; i++)
                Assert.StartsWith($"| {KernelCatalog.Names[i]} |", markdown[vector + 2 + i]);
            Assert.StartsWith("| geometric mean |", markdown[vector + 2 + KernelCatalog.Names.Count]);
            var model = Array.FindIndex(markdown, l => l.StartsWith("| kernel | estimated cycles |", StringComparison.Ordinal));
            Assert.True(model > header, "no cost-model table");
            for (var i = 0; i < KernelCatalog.Names.Count; i++)
                Assert.StartsWith($"| {KernelCatalog.Names[i]} |", markdown[model + 2 + i]);
            Assert.Contains(markdown, l => l.StartsWith("Rank correlation (Spearman) with the measured times", StringComparison.Ordinal));
            var png = File.ReadAllBytes(Path.Combine(folder, ReportCommand.ChartFile));
            Assert.Equal(0x89, png[0]);
            Assert.Empty(Directory.GetFiles(folder, "*.tmp"));
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    [Fact]
    public void Vector_only_is_an_option_of_its_own()
    {
        var options = ReportOptions.Parse(["--vector-only", "--out", "o", "--dsl", "d"], out var error);
        Assert.Null(error);
        Assert.True(options!.VectorOnly);
        Assert.False(ReportOptions.Parse(["--quick", "--out", "o", "--dsl", "d"], out _)!.VectorOnly);
        Assert.Contains("--vector-only", ReportOptions.Usage);
    }

    [Fact]
    public void Unknown_arguments_are_a_usage_error_and_write_nothing()
    {
        var folder = Path.Combine(Path.GetTempPath(), "gmac-bench-never-" + Guid.NewGuid().ToString("N"));
        var error = new StringWriter();
        var code = ReportCommand.Run(["--fast", "--out", folder], new StringWriter(), error);
        Assert.Equal(2, code);
        Assert.Contains("unknown argument '--fast'", error.ToString());
        Assert.False(Directory.Exists(folder));
    }

    [Fact]
    public void A_missing_dsl_folder_is_an_error_with_its_name()
    {
        var folder = Directory.CreateTempSubdirectory("gmac-bench-report-").FullName;
        try
        {
            var error = new StringWriter();
            var code = ReportCommand.Run(["--quick", "--out", folder, "--dsl", Path.Combine(folder, "nope")], new StringWriter(), error);
            Assert.Equal(1, code);
            Assert.Contains("nope", error.ToString());
            Assert.Empty(Directory.GetFiles(folder));
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }
}
