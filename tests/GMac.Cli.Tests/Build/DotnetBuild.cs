using System.Diagnostics;
using System.Reflection;

namespace GMac.Cli.Tests.Build;

/// <summary>
/// Runs <c>dotnet build</c> on a project outside the repository, in the configuration this test
/// assembly was built in, so that the project's reference to the gmac tool resolves to the
/// tool already built next to the tests instead of building it again.
/// </summary>
internal static class DotnetBuild
{
    // A safety net against a hung build only; a build normally takes seconds.
    private static readonly TimeSpan Timeout = TimeSpan.FromMinutes(5);

    /// <summary>The configuration of this test assembly, hence of the gmac tool built with it.</summary>
    public static string Configuration =>
        typeof(DotnetBuild).Assembly.GetCustomAttribute<AssemblyConfigurationAttribute>()?.Configuration ?? "Debug";

    public static (int Exit, string Output) Run(string projectFile, bool restore)
    {
        var start = new ProcessStartInfo(Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") ?? "dotnet")
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            WorkingDirectory = Path.GetDirectoryName(projectFile)!,
        };
        foreach (var argument in new[]
                 {
                     "build", projectFile, "-c", Configuration, "-v:normal", "-nodeReuse:false",
                     "-p:UseSharedCompilation=false", "-p:BuildProjectReferences=false",
                 })
            start.ArgumentList.Add(argument);
        if (!restore) start.ArgumentList.Add("--no-restore");

        // The test host may run under an MSBuild of its own; its settings must not leak into this build.
        foreach (var name in start.Environment.Keys.Where(k => k.StartsWith("MSBUILD", StringComparison.OrdinalIgnoreCase)).ToList())
            start.Environment.Remove(name);
        start.Environment["MSBUILDDISABLENODEREUSE"] = "1";
        start.Environment["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1";
        start.Environment["DOTNET_NOLOGO"] = "1";
        start.Environment["DOTNET_CLI_UI_LANGUAGE"] = "en";

        using var process = Process.Start(start)!;
        var output = process.StandardOutput.ReadToEndAsync();
        var error = process.StandardError.ReadToEndAsync();
        if (!process.WaitForExit(Timeout))
        {
            process.Kill(entireProcessTree: true);
            throw new TimeoutException($"dotnet build of {projectFile} did not finish within {Timeout}");
        }
        return (process.ExitCode, output.Result + error.Result);
    }
}
