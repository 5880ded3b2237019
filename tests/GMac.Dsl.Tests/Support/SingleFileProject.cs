namespace GMac.Dsl.Tests.Support;

/// <summary>A DSL project of one in-memory file.</summary>
internal static class SingleFileProject
{
    public static DslProject Bind(string text, string path = "test.gmac") => DslProject.FromSources([(path, text)]);
}
