namespace GMac.Cli.BindingPoints;

/// <summary>The C# files under the given paths, skipping build output (<c>bin/</c>, <c>obj/</c>) and hidden folders.</summary>
internal static class SourceScanner
{
    public static (List<string> Files, List<BindingDiagnostic> Missing) Find(IReadOnlyList<string> paths)
    {
        var files = new SortedSet<string>(StringComparer.Ordinal);
        var missing = new List<BindingDiagnostic>();
        foreach (var path in paths)
        {
            if (File.Exists(path)) files.Add(Path.GetFullPath(path));
            else if (Directory.Exists(path)) Walk(new DirectoryInfo(path), files);
            else missing.Add(new BindingDiagnostic(path, 1, 1, "GMAC0407", $"path '{path}' does not exist"));
        }
        return (files.ToList(), missing);
    }

    private static void Walk(DirectoryInfo directory, SortedSet<string> files)
    {
        foreach (var file in directory.EnumerateFiles("*.cs")) files.Add(file.FullName);
        foreach (var sub in directory.EnumerateDirectories())
        {
            if (sub.Name is "bin" or "obj" || sub.Name.StartsWith('.')) continue;
            Walk(sub, files);
        }
    }
}
