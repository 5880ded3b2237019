namespace SafeFiles;

/// <summary>
/// The files matching a pattern under a folder, for tools that read them all: only regular files
/// (a FIFO or device would block or never end), each file and each directory once however many
/// links lead to it (a link to an ancestor would otherwise be followed until the system gives up).
/// </summary>
public static class SourceTree
{
    /// <summary>
    /// Lists <paramref name="root"/> recursively, sorted by path; folders for which
    /// <paramref name="skipFolder"/> (given the folder name) is true are not entered.
    /// </summary>
    public static SourceTreeListing List(string root, string pattern, Func<string, bool>? skipFolder = null)
    {
        var walk = new Walk(pattern, skipFolder ?? (_ => false));
        walk.Visit(root);
        walk.Files.Sort(StringComparer.Ordinal);
        return new SourceTreeListing(walk.Files, walk.Skipped);
    }

    /// <summary>Whether a single named file should be read: null if so, else why not.</summary>
    public static string? WhyNotReadable(string file) =>
        FileStat.KindOf(file) == FileKind.Special ? "not a regular file (a FIFO, socket or device); skipped" : null;

    private sealed class Walk(string pattern, Func<string, bool> skipFolder)
    {
        private readonly HashSet<string> _folders = new(StringComparer.Ordinal);
        private readonly HashSet<string> _realFiles = new(StringComparer.Ordinal);

        public List<string> Files { get; } = [];
        public List<SkippedFile> Skipped { get; } = [];

        /// <summary>Paths are reported under <paramref name="folder"/> as given (relative stays relative).</summary>
        public void Visit(string folder)
        {
            try
            {
                if (!_folders.Add(RealPath.Of(folder))) return;
                var info = new DirectoryInfo(folder);
                foreach (var name in info.EnumerateFiles(pattern).Select(f => f.Name).Order(StringComparer.Ordinal))
                {
                    var file = Path.Join(folder, name);
                    if (WhyNotReadable(file) is { } why) Skipped.Add(new SkippedFile(file, why, IsError: false));
                    else if (RealFile(file) is { } real && _realFiles.Add(real)) Files.Add(file);
                }
                foreach (var name in info.EnumerateDirectories().Select(d => d.Name).Order(StringComparer.Ordinal))
                    if (!skipFolder(name)) Visit(Path.Join(folder, name));
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                Skipped.Add(new SkippedFile(folder, $"cannot list the folder: {e.Message}", IsError: true));
            }
        }

        private string? RealFile(string file)
        {
            try
            {
                return RealPath.Of(file);
            }
            catch (IOException e)
            {
                Skipped.Add(new SkippedFile(file, $"cannot read file: {e.Message}", IsError: true));
                return null;
            }
        }
    }
}
