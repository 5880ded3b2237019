using System.Diagnostics;
using System.Globalization;
using GMac.Benchmarks.Generation;

namespace GMac.Benchmarks.Reporting;

/// <summary>
/// The generated / hand ratio of a kernel as the median over several fresh processes, each running
/// <c>kernels --ratio</c> (a median over pairs of slices), every other one compiling the hand code
/// first (an even count balances the two orders; the median is then the mean of the middle two),
/// with the JIT's loop alignment off (see <see cref="RunOnce"/>). Within one process the two loops' machine code is fixed, but where the JIT puts it and when
/// it replaces its first code are not: identical arithmetic was measured at ratios from 0.92 to 1.30
/// in five processes, steady within each. One process's figure is one draw of that; the median of
/// several is the kernel's.
/// </summary>
public sealed class ProcessRatioTimer(int processes)
{
    public (double Median, double Min, double Max) GeneratedOverHand(string kernel)
    {
        var ratios = Enumerable.Range(0, processes).Select(p => RunOnce(kernel, handFirst: p % 2 == 1)).ToList();
        return (GenerationTimer.Median(ratios), ratios.Min(), ratios.Max());
    }

    /// <summary>The dotnet host: the one running this process where that is it (dotnet run, dotnet test), else the one on the path.</summary>
    private static string DotnetHost() =>
        Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") is { Length: > 0 } host ? host
        : Path.GetFileNameWithoutExtension(Environment.ProcessPath) == "dotnet" ? Environment.ProcessPath!
        : "dotnet";

    private static double RunOnce(string kernel, bool handFirst)
    {
        var start = new ProcessStartInfo(DotnetHost())
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
            WorkingDirectory = Directory.GetCurrentDirectory(),
        };
        start.ArgumentList.Add(typeof(ProcessRatioTimer).Assembly.Location);
        // The JIT pads the code before a loop to align it. On loops of a few instructions that padding,
        // not the code, decided the ratio: Circ3 (identical arithmetic) measured 0.77 in every process
        // compiling the generated code first and 1.30 in every one compiling the hand code first, and
        // 0.99-1.01 in both orders without it. Both variants run without it; the time columns keep it.
        start.Environment["DOTNET_JitAlignLoops"] = "0";
        foreach (var a in (string[])["kernels", "--ratio", .. handFirst ? ["--hand-first"] : Array.Empty<string>(), kernel]) start.ArgumentList.Add(a);
        using var process = Process.Start(start) ?? throw new InvalidOperationException($"cannot start {start.FileName}");
        var stderr = process.StandardError.ReadToEndAsync();
        var stdout = process.StandardOutput.ReadToEnd();
        process.WaitForExit();
        var line = stdout.Split('\n').FirstOrDefault(l => l.StartsWith(KernelsCommand.RatioLine + " " + kernel + " ", StringComparison.Ordinal));
        if (process.ExitCode != 0 || line is null)
            throw new InvalidOperationException($"timing {kernel} in its own process failed (exit {process.ExitCode}): {stderr.Result.Trim()}");
        return double.Parse(line.Split(' ')[2], CultureInfo.InvariantCulture);
    }
}
