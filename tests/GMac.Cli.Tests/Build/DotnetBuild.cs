using System.Reflection;

namespace GMac.Cli.Tests.Build;

/// <summary>
/// Runs <c>dotnet build</c> on a project outside the repository, in the configuration this test
/// assembly was built in, so that the project's reference to the gmac tool resolves to the
/// tool already built next to the tests instead of building it again.
/// </summary>
internal static class DotnetBuild
{
    /// <summary>The configuration of this test assembly, hence of the gmac tool built with it.</summary>
    public static string Configuration =>
        typeof(DotnetBuild).Assembly.GetCustomAttribute<AssemblyConfigurationAttribute>()?.Configuration ?? "Debug";

    public static (int Exit, string Output) Run(string projectFile, bool restore)
    {
        List<string> arguments =
        [
            "build", projectFile, "-c", Configuration, "-v:normal", "-nodeReuse:false",
            "-p:UseSharedCompilation=false", "-p:BuildProjectReferences=false",
        ];
        if (!restore) arguments.Add("--no-restore");
        return DotnetCommand.Run(Path.GetDirectoryName(projectFile)!, arguments);
    }
}
