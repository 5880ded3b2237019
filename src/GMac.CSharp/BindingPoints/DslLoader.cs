using GMac.CSharp.Emit;
using GMac.Dsl;

namespace GMac.CSharp.BindingPoints;

/// <summary>Loads the DSL for a command and prints its errors (with those of its output blocks as C#); null when it has any.</summary>
internal static class DslLoader
{
    /// <summary>Binds the folders and files together; <paramref name="cacheDirectory"/> null keeps the simplification cache in memory.</summary>
    public static GenerationContext? Load(IReadOnlyList<string> sources, string? cacheDirectory, TextWriter error)
    {
        var project = DslProject.Load(sources);
        var errors = OutputBlockCheck.Diagnostics(project).Where(d => d.IsError).ToList();
        foreach (var d in errors) error.WriteLine(d);
        return errors.Count > 0 ? null : new GenerationContext(project, cacheDirectory);
    }
}
