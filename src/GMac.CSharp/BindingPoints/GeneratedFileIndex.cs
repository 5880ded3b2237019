using System.Security.Cryptography;
using System.Text;
using SafeFiles;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// Remembers, in the cache folder, the content hash of each file the tool last left up to date and
/// under which DSL and tool it did, so an unchanged file is not generated again (generation takes
/// hundreds of milliseconds per region even with every simplification cached). Losing or corrupting
/// the index only costs time: every entry is checked against the file's current bytes.
/// </summary>
internal sealed class GeneratedFileIndex
{
    public const string FileName = "generated-files.tsv";

    private readonly string? _path;
    private readonly string _key;
    private readonly Dictionary<string, string> _entries = new(StringComparer.Ordinal);
    private bool _dirty;

    private GeneratedFileIndex(string? path, string key)
    {
        _path = path;
        _key = key;
    }

    /// <summary>
    /// An index for one DSL and one set of options; memory-only when <paramref name="cacheDirectory"/> is null.
    /// <paramref name="stats"/> is null for a check, which accepts regions with or without statistics.
    /// </summary>
    public static GeneratedFileIndex Open(string? cacheDirectory, GenerationContext context, bool? stats)
    {
        var key = new StringBuilder();
        key.Append(GenerationContext.ToolVersion).Append('|').Append(stats?.ToString() ?? "either").Append('|');
        // A float run must not take a file left current by a double run for current.
        if (context.DefaultScalarType != "double") key.Append(context.DefaultScalarType).Append('|');
        if (context.DefaultFusedMultiplyAdd) key.Append("fma|");
        foreach (var tree in context.Project.SyntaxTrees.OrderBy(t => t.FilePath, StringComparer.Ordinal))
            key.Append(tree.FilePath).Append('\0').Append(tree.Text).Append('\0');
        var index = new GeneratedFileIndex(cacheDirectory is null ? null : Path.Combine(cacheDirectory, FileName), Hash(Encoding.UTF8.GetBytes(key.ToString())));
        index.Load();
        return index;
    }

    public bool IsCurrent(string path, byte[] content) =>
        _entries.TryGetValue(path, out var recorded) && recorded == $"{_key}:{Hash(content)}";

    public void Record(string path, byte[] content)
    {
        _entries[path] = $"{_key}:{Hash(content)}";
        _dirty = true;
    }

    public void Save()
    {
        if (_path is null || !_dirty) return;
        var text = new StringBuilder();
        foreach (var (path, value) in _entries.OrderBy(e => e.Key, StringComparer.Ordinal)) text.Append(path).Append('\t').Append(value).Append('\n');
        try
        {
            Directory.CreateDirectory(Path.GetDirectoryName(_path)!);
            AtomicFile.TryWrite(_path, Encoding.UTF8.GetBytes(text.ToString()));
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // only a cache: the next run regenerates
        }
    }

    private void Load()
    {
        if (_path is null || !File.Exists(_path)) return;
        try
        {
            foreach (var line in File.ReadAllLines(_path))
            {
                var parts = line.Split('\t');
                if (parts.Length == 2) _entries[parts[0]] = parts[1];
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            _entries.Clear();
        }
    }

    private static string Hash(byte[] bytes) => Convert.ToHexString(SHA256.HashData(bytes));
}
