using GMac.Dsl;

namespace GMac.Cli.BindingPoints;

/// <summary>Loads the DSL for a command and prints its errors; null when it has any.</summary>
internal static class DslLoader
{
    public static GenerationContext? Load(string dsl, string? cache, TextWriter error)
    {
        var project = DslProject.Load(dsl);
        var errors = project.Diagnostics.Where(d => d.IsError).ToList();
        foreach (var d in errors) error.WriteLine(d);
        return errors.Count > 0 ? null : new GenerationContext(project, cache ?? GenerationContext.DefaultCacheDirectory(dsl));
    }
}
