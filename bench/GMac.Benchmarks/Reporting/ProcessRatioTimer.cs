using System.Diagnostics;
using System.Globalization;
using GMac.Benchmarks.Generation;

namespace GMac.Benchmarks.Reporting;

/// <summary>
/// The generated / hand ratio of a kernel as the median over several fresh processes, each running
/// <c>kernels --ratio</c> (a median over pairs of slices), every other one compiling the hand code
/// first (an even count balances the two orders; the median is then the mean of the middle two),
/// each with its code placed elsewhere (<see cref="CodePlacement"/>: process p compiles
/// <see cref="ShiftStep"/>·p other methods first), with the JIT's loop alignment off (see
/// <see cref="RunOnce"/>). Within one process the two loops' machine code is fixed, but where the JIT
/// puts it is not: the third-degree Julia step measured 0.77, 0.96 or 1.25 of its hand code by
/// placement alone, and without the shifts every process of one compile order drew the same placement.
/// One process's figure is one draw; the median of several is the kernel's.
/// </summary>
public sealed class ProcessRatioTimer(int processes)
{
    public (double Median, double Min, double Max) GeneratedOverHand(string kernel)
    {
        var ratios = Enumerable.Range(0, processes).Select(p => RunOnce(kernel, handFirst: p % 2 == 1, ShiftStep * p)).ToList();
        return (GenerationTimer.Median(ratios), ratios.Min(), ratios.Max());
    }

    /// <summary>The dotnet host: the one running this process where that is it (dotnet run, dotnet test), else the one on the path.</summary>
    private static string DotnetHost() =>
        Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") is { Length: > 0 } host ? host
        : Path.GetFileNameWithoutExtension(Environment.ProcessPath) == "dotnet" ? Environment.ProcessPath!
        : "dotnet";

    /// <summary>Methods compiled before the kernels per process index (any step that moves the code by more than a line would do).</summary>
    public const int ShiftStep = 5;

    private static double RunOnce(string kernel, bool handFirst, int codeShift)
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
        foreach (var a in (string[])["kernels", "--ratio", .. handFirst ? ["--hand-first"] : Array.Empty<string>(), "--code-shift", codeShift.ToString(CultureInfo.InvariantCulture), kernel])
            start.ArgumentList.Add(a);
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
