namespace GMac.Benchmarks.Tests.Support;

/// <summary>Folders of the repository the tests run in.</summary>
public static class RepositoryPaths
{
    public static string Root { get; } = FindRoot();

    public static string Dsl => Path.Combine(Root, "dsl");

    private static string FindRoot()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
            if (File.Exists(Path.Combine(dir.FullName, "GMac.sln"))) return dir.FullName;
        throw new InvalidOperationException("GMac.sln not found above the test assembly.");
    }
}
