using GMac.Dsl.Diagnostics;
using SafeFiles;

namespace GMac.Cli.LanguageServer;

/// <summary>
/// The DSL folders and the open documents over them. Every change starts a new analysis after a
/// short pause (the newest change wins: an older one still waiting or running is cancelled and its
/// result dropped); a request that needs the current text analyses it at once.
/// </summary>
internal sealed class Workspace(IReadOnlyList<string> folders, bool wholeWorkspace, Func<PublishDiagnosticsParams, Task> publish, TextWriter log)
{
    // Copies of .gmac files a build or a tool makes (gmac.dll's own library under bin/) would define everything twice.
    private static readonly string[] NotSources = ["bin", "obj", "node_modules"];

    public static readonly TimeSpan Debounce = TimeSpan.FromMilliseconds(150);

    private readonly Dictionary<string, string> _open = new(StringComparer.Ordinal);
    private readonly Lock _lock = new();
    private readonly SemaphoreSlim _analysing = new(1, 1);
    private readonly SemaphoreSlim _publishing = new(1, 1);
    private readonly HashSet<string> _published = new(StringComparer.Ordinal);
    private int _version;
    private Analysis? _current;
    private CancellationTokenSource _pending = new();

    public IReadOnlyList<string> Folders { get; } = folders;

    public void Open(string path, string text) => Update(path, text);

    public void Change(string path, string text) => Update(path, text);

    public void Close(string path)
    {
        lock (_lock) _open.Remove(path);
        // The file on disk (or its absence) counts again.
        Schedule();
    }

    /// <summary>A file on disk changed: re-read it unless it is open.</summary>
    public void FilesChanged() => Schedule();

    private void Update(string path, string text)
    {
        lock (_lock) _open[path] = text;
        Schedule();
    }

    private void Schedule()
    {
        CancellationToken token;
        lock (_lock)
        {
            _version++;
            _pending.Cancel();
            _pending.Dispose();
            _pending = new CancellationTokenSource();
            token = _pending.Token;
        }
        _ = Task.Run(async () =>
        {
            try
            {
                await Task.Delay(Debounce, token);
                var analysis = await CurrentAsync(token);
                await PublishAsync(analysis, token);
            }
            catch (OperationCanceledException)
            {
                // A newer change has its own analysis coming.
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                await log.WriteLineAsync($"gmac lsp: analysis failed: {e}");
            }
        }, CancellationToken.None);
    }

    /// <summary>Whether no change came after <paramref name="analysis"/>'s texts.</summary>
    public bool IsCurrent(Analysis analysis)
    {
        lock (_lock) return analysis.Version == _version;
    }

    /// <summary>The analysis of the current texts, made now if the last one is older.</summary>
    public async Task<Analysis> CurrentAsync(CancellationToken cancellation)
    {
        await _analysing.WaitAsync(cancellation);
        try
        {
            int version;
            List<(string Path, string Text)> sources;
            lock (_lock)
            {
                if (_current is { } current && current.Version == _version) return current;
                version = _version;
                sources = Sources();
            }
            var analysis = await Task.Run(() => new Analysis(version, sources), cancellation);
            lock (_lock)
            {
                if (_current is null || _current.Version < version) _current = analysis;
            }
            return analysis;
        }
        finally
        {
            _analysing.Release();
        }
    }

    /// <summary>Every <c>.gmac</c> file of the folders (an open document's text over its file), then open documents outside them.</summary>
    private List<(string Path, string Text)> Sources()
    {
        var sources = new List<(string, string)>();
        var seen = new HashSet<string>(StringComparer.Ordinal);
        foreach (var folder in Folders)
        {
            IEnumerable<string> files;
            try
            {
                files = File.Exists(folder) ? [folder] : Directory.Exists(folder) ? SourceTree.List(folder, "*.gmac").Files : [];
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                log.WriteLine($"gmac lsp: cannot list '{folder}': {e.Message}");
                continue;
            }
            foreach (var file in files.Select(Path.GetFullPath))
            {
                if (wholeWorkspace && IsOutput(folder, file)) continue;
                if (!seen.Add(file)) continue;
                if (_open.TryGetValue(file, out var text)) sources.Add((file, text));
                else
                {
                    try
                    {
                        sources.Add((file, File.ReadAllText(file)));
                    }
                    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
                    {
                        log.WriteLine($"gmac lsp: cannot read '{file}': {e.Message}");
                    }
                }
            }
        }
        foreach (var (path, text) in _open)
            if (seen.Add(path)) sources.Add((path, text));
        return sources;
    }

    /// <summary>Whether a file found under a workspace folder lies in build output or a hidden folder.</summary>
    private static bool IsOutput(string folder, string file) =>
        Path.GetRelativePath(folder, file).Split(Path.DirectorySeparatorChar).SkipLast(1)
            .Any(d => d.StartsWith('.') || NotSources.Contains(d, StringComparer.OrdinalIgnoreCase));

    /// <summary>The diagnostics of every file, and an empty list for each open document or file that had some and has none now.</summary>
    private async Task PublishAsync(Analysis analysis, CancellationToken cancellation)
    {
        var byFile = analysis.Diagnostics.GroupBy(d => d.Span.FilePath, StringComparer.Ordinal).ToDictionary(g => g.Key, g => g.ToList(), StringComparer.Ordinal);
        // One analysis publishes at a time and stops at a newer change, so an older list never follows a newer one.
        await _publishing.WaitAsync(cancellation);
        try
        {
            List<string> files;
            // Open documents always get a list, so an editor never keeps problems of an older text.
            lock (_lock) files = [.. _published.Union(byFile.Keys).Union(_open.Keys)];
            foreach (var file in files)
            {
                cancellation.ThrowIfCancellationRequested();
                var diagnostics = byFile.TryGetValue(file, out var list) ? list.Select(d => ToLsp(analysis, d)).ToList() : [];
                await publish(new PublishDiagnosticsParams(Uris.FromPath(file), diagnostics));
                lock (_lock)
                {
                    if (diagnostics.Count > 0) _published.Add(file);
                    else _published.Remove(file);
                }
            }
        }
        finally
        {
            _publishing.Release();
        }
    }

    private static LspDiagnostic ToLsp(Analysis analysis, Diagnostic d)
    {
        var text = analysis.Texts.TryGetValue(d.Span.FilePath, out var t) ? t : new SourceText(d.Span.FilePath, "");
        var start = text.OffsetOf(d.Span.Line, d.Span.Column);
        // A diagnostic known only by its start covers the token there.
        var length = d.Span.Length > 0 ? d.Span.Length : text.TokenLengthAt(start);
        return new LspDiagnostic(text.RangeOf(start, length), d.IsError ? 1 : 2, d.Code, "gmac", d.Message);
    }
}
