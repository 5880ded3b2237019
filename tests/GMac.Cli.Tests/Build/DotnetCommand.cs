using System.Diagnostics;

namespace GMac.Cli.Tests.Build;

/// <summary>
/// Runs the <c>dotnet</c> command line as a user would, in a folder of its own: the test host's
/// MSBuild settings do not leak in, and <paramref name="environment"/> adds variables (such as a
/// private NUGET_PACKAGES folder).
/// </summary>
internal static class DotnetCommand
{
    // A safety net against a hung command only; each normally takes seconds.
    private static readonly TimeSpan Timeout = TimeSpan.FromMinutes(5);

    public static (int Exit, string Output) Run(string workingDirectory, IEnumerable<string> arguments, IReadOnlyDictionary<string, string>? environment = null)
    {
        var start = new ProcessStartInfo(Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") ?? "dotnet")
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            RedirectStandardInput = true,
            WorkingDirectory = workingDirectory,
        };
        foreach (var argument in arguments) start.ArgumentList.Add(argument);

        // The test host may run under an MSBuild of its own; its settings must not leak into this command.
        foreach (var name in start.Environment.Keys.Where(k => k.StartsWith("MSBUILD", StringComparison.OrdinalIgnoreCase)).ToList())
            start.Environment.Remove(name);
        start.Environment["MSBUILDDISABLENODEREUSE"] = "1";
        start.Environment["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1";
        start.Environment["DOTNET_NOLOGO"] = "1";
        start.Environment["DOTNET_CLI_UI_LANGUAGE"] = "en";
        foreach (var (name, value) in environment ?? new Dictionary<string, string>()) start.Environment[name] = value;

        using var process = Process.Start(start)!;
        process.StandardInput.Close();
        var output = process.StandardOutput.ReadToEndAsync();
        var error = process.StandardError.ReadToEndAsync();
        if (!process.WaitForExit(Timeout))
        {
            process.Kill(entireProcessTree: true);
            throw new TimeoutException($"dotnet {string.Join(' ', start.ArgumentList)} did not finish within {Timeout}");
        }
        return (process.ExitCode, output.Result + error.Result);
    }
}
