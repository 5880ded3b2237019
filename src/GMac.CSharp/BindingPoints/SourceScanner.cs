using GMac.Dsl.Diagnostics;
using SafeFiles;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// The C# files under the given paths, skipping build output (<c>bin/</c>, <c>obj/</c>), hidden
/// folders and special files, each file listed once however many links lead to it. A file named
/// on the command line is read only if it is a <c>.cs</c> file; any other is skipped with a warning.
/// </summary>
internal static class SourceScanner
{
    public static (List<string> Files, List<Diagnostic> Missing) Find(IReadOnlyList<string> paths)
    {
        var scan = Scan(paths);
        return (scan.Files, scan.Problems);
    }

    /// <summary>The files, the paths that could not be scanned (errors) and the files left out (warnings).</summary>
    public static SourceScan Scan(IReadOnlyList<string> paths)
    {
        var files = new SortedSet<string>(StringComparer.Ordinal);
        var seen = new HashSet<string>(StringComparer.Ordinal);
        var problems = new List<Diagnostic>();
        var skipped = new List<Diagnostic>();
        void Add(string file)
        {
            try
            {
                if (seen.Add(RealPath.Of(file))) files.Add(Path.GetFullPath(file));
            }
            catch (IOException e)
            {
                // the links along the path loop
                problems.Add(new Diagnostic(DiagnosticCodes.CannotReadSource, SourceSpan.None(file), e.Message));
            }
        }
        foreach (var path in paths)
        {
            if (File.Exists(path))
            {
                if (SourceTree.WhyNotReadable(path) is { } why) skipped.Add(Skipped(path, why));
                // as in a folder, only C# sources: 'gmac generate *' must not rewrite regions of a README
                else if (!IsCSharpSource(path)) skipped.Add(Skipped(path, "not a C# source file (only .cs files are generated); skipped"));
                else Add(path);
            }
            else if (Directory.Exists(path))
            {
                var listing = SourceTree.List(path, "*.cs", name => name is "bin" or "obj" || name.StartsWith('.'));
                foreach (var file in listing.Files) Add(file);
                foreach (var s in listing.Skipped)
                {
                    if (s.IsError) problems.Add(new Diagnostic(DiagnosticCodes.CannotReadSource, SourceSpan.None(s.Path), s.Reason));
                    else skipped.Add(Skipped(s.Path, s.Reason));
                }
            }
            else problems.Add(new Diagnostic(DiagnosticCodes.CannotReadSource, SourceSpan.None(path), $"path '{path}' does not exist"));
        }
        return new SourceScan(files.ToList(), problems, skipped);
    }

    private static bool IsCSharpSource(string path) => Path.GetExtension(path).Equals(".cs", StringComparison.OrdinalIgnoreCase);

    private static Diagnostic Skipped(string path, string reason) =>
        new(DiagnosticCodes.SkippedSourceFile, SourceSpan.None(Path.GetFullPath(path)), reason);
}
