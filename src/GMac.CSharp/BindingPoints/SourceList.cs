using GMac.Dsl.Diagnostics;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// A file naming the C# files to work on, one path a line (what <c>gmac generate --sources-from</c>
/// reads; the MSBuild step writes the project's <c>Compile</c> items into one). Blank lines are
/// skipped; a relative path is taken from the list's own folder, so the list means the same files
/// whatever folder gmac runs in.
/// </summary>
internal static class SourceList
{
    /// <summary>The listed paths, made absolute; null (with a diagnostic) when the list cannot be read.</summary>
    public static IReadOnlyList<string>? Read(string listFile, TextWriter error, string what = "source files")
    {
        var full = Path.GetFullPath(listFile);
        string[] lines;
        try
        {
            lines = Directory.Exists(full)
                ? throw new IOException($"'{listFile}' is a folder, not a list of files")
                : File.ReadAllLines(full);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            error.WriteLine(new Diagnostic(DiagnosticCodes.CannotReadSource, SourceSpan.None(full), $"cannot read the list of {what}: {e.Message}"));
            return null;
        }
        var folder = Path.GetDirectoryName(full)!;
        return lines.Where(l => !string.IsNullOrWhiteSpace(l)).Select(l => Path.GetFullPath(l, folder)).ToList();
    }
}
