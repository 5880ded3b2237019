using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.Docs;

/// <summary>
/// A fenced code block of a Markdown file of the repository: its file (relative to the root), the
/// line of its opening fence, the info string's words and its text (de-indented to the fence).
/// </summary>
internal sealed record MarkdownCodeBlock(string File, int Line, IReadOnlyList<string> Info, string Text)
{
    public string Language => Info.Count > 0 ? Info[0].ToLowerInvariant() : "";

    public string Where => $"{File}:{Line}";

    /// <summary>README.md and every Markdown file under docs/, in a stable order.</summary>
    public static IReadOnlyList<string> DocumentFiles()
    {
        var root = SharedDsl.RepositoryRoot;
        var docs = Directory.EnumerateFiles(Path.Combine(root, "docs"), "*.md", SearchOption.AllDirectories)
            .Select(p => Path.GetRelativePath(root, p).Replace('\\', '/'))
            .Order(StringComparer.Ordinal);
        return ["README.md", .. docs];
    }

    public static IReadOnlyList<MarkdownCodeBlock> All() => DocumentFiles().SelectMany(Read).ToList();

    /// <summary>The fenced blocks (``` or ~~~, possibly indented in a list) of one file.</summary>
    public static IEnumerable<MarkdownCodeBlock> Read(string file)
    {
        var lines = System.IO.File.ReadAllText(Path.Combine(SharedDsl.RepositoryRoot, file)).ReplaceLineEndings("\n").Split('\n');
        for (var i = 0; i < lines.Length; i++)
        {
            var trimmed = lines[i].TrimStart();
            var fence = trimmed.StartsWith("```", StringComparison.Ordinal) ? "```" : trimmed.StartsWith("~~~", StringComparison.Ordinal) ? "~~~" : null;
            if (fence is null) continue;
            var indent = lines[i].Length - trimmed.Length;
            var info = trimmed.TrimStart(fence[0]).Split(' ', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);
            var start = i;
            var body = new List<string>();
            for (i++; i < lines.Length && !lines[i].TrimStart().StartsWith(fence, StringComparison.Ordinal); i++)
                body.Add(lines[i].Length >= indent && string.IsNullOrWhiteSpace(lines[i][..indent]) ? lines[i][indent..] : lines[i].TrimStart());
            yield return new MarkdownCodeBlock(file, start + 1, info, body.Count == 0 ? "" : string.Join("\n", body) + "\n");
        }
    }
}
