using GMac.Cli.Commands;
using GMac.Dsl;

namespace GMac.Cli.BindingPoints;

/// <summary>Loads the DSL for a command and prints its errors; null when it has any.</summary>
internal static class DslLoader
{
    public static GenerationContext? Load(string dsl, string? cache, TextWriter error) => Load([dsl], cache, error);

    /// <summary>Binds the folders and files together; the cache defaults to the first one's (see <see cref="DslOptions.DefaultCacheDirectory"/>).</summary>
    public static GenerationContext? Load(IReadOnlyList<string> sources, string? cache, TextWriter error)
    {
        var project = DslProject.Load(sources);
        var errors = project.Diagnostics.Where(d => d.IsError).ToList();
        foreach (var d in errors) error.WriteLine(d);
        return errors.Count > 0 ? null : new GenerationContext(project, cache ?? DslOptions.DefaultCacheDirectory(sources));
    }
}
