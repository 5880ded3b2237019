using GMac.CSharp.BindingPoints;
using GMac.Dsl;

namespace GMac.CSharp.Tests.Support;

/// <summary>The repository's DSL library, loaded once for all tests (memory-only simplification cache).</summary>
internal static class SharedDsl
{
    private static readonly Lazy<GenerationContext> Lazy = new(() => new GenerationContext(DslProject.Load(DslDirectory), cacheDirectory: null));

    public static GenerationContext Context => Lazy.Value;

    public static string RepositoryRoot
    {
        get
        {
            var dir = new DirectoryInfo(AppContext.BaseDirectory);
            while (dir is not null && !File.Exists(Path.Combine(dir.FullName, "GMac.sln"))) dir = dir.Parent;
            return dir!.FullName;
        }
    }

    public static string DslDirectory => Path.Combine(RepositoryRoot, "dsl");
}
