using System.Collections.Concurrent;
using System.Globalization;
using System.Text;

namespace GMac.Core.Symbolic;

/// <summary>
/// Remembers simplification answers by canonical key, in memory and optionally on disk so they
/// survive runs. The disk form is one append-only text file of <c>key TAB result TAB checksum</c>
/// lines, results in the shared text form (each function and inverse written once): loaded lazily on the first lookup, appended and flushed per answer, and safe to delete.
/// Lines that are truncated, corrupted or unreadable are ignored. Thread-safe.
/// </summary>
public sealed class SimplificationCache
{
    public const string FileName = "scalar-simplify-cache.tsv";

    private readonly ConcurrentDictionary<string, Scalar> _memory = new(StringComparer.Ordinal);
    private readonly object _diskLock = new();
    private Dictionary<string, string>? _disk;
    private long _hits;
    private long _diskHits;
    private long _misses;
    private long _writeFailures;

    /// <summary>A cache in memory and, when <paramref name="directory"/> is given, in a file there.</summary>
    public SimplificationCache(string? directory = null)
    {
        FilePath = directory is null ? null : Path.Combine(Path.GetFullPath(directory), FileName);
    }

    /// <summary>The on-disk file, or null for a memory-only cache.</summary>
    public string? FilePath { get; }

    /// <summary>Lookups answered (from memory or from disk).</summary>
    public long Hits => Interlocked.Read(ref _hits);

    /// <summary>The part of <see cref="Hits"/> answered from the file written by an earlier run.</summary>
    public long DiskHits => Interlocked.Read(ref _diskHits);

    public long Misses => Interlocked.Read(ref _misses);

    /// <summary>Answers that could not be written to disk (the cache stays correct, only colder).</summary>
    public long WriteFailures => Interlocked.Read(ref _writeFailures);

    public int Count => _memory.Count;

    public bool TryGet(string key, out Scalar result)
    {
        ArgumentNullException.ThrowIfNull(key);
        if (_memory.TryGetValue(key, out result!))
        {
            Interlocked.Increment(ref _hits);
            return true;
        }
        if (TryGetFromDisk(key, out result))
        {
            _memory.TryAdd(key, result);
            Interlocked.Increment(ref _hits);
            Interlocked.Increment(ref _diskHits);
            return true;
        }
        Interlocked.Increment(ref _misses);
        result = Scalar.Zero;
        return false;
    }

    public void Add(string key, Scalar result)
    {
        ArgumentNullException.ThrowIfNull(key);
        ArgumentNullException.ThrowIfNull(result);
        if (key.AsSpan().IndexOfAny('\t', '\n', '\r') >= 0)
            throw new ArgumentException("A cache key cannot contain tabs or line breaks.", nameof(key));
        if (!_memory.TryAdd(key, result) || FilePath is null) return;
        var text = ScalarPrinter.FormatShared(result);
        var line = $"{key}\t{text}\t{Checksum(key, text)}\n";
        bool flushNow;
        lock (_diskLock)
        {
            if (_pending.Length == 0) EnsureFlushAtExit();
            _pending.Append(line);
            flushNow = ++_pendingCount >= FlushThreshold;
        }
        if (flushNow) Flush();
    }

    /// <summary>Answers appended since the last flush; written in one append so misses cost no file I/O each.</summary>
    private readonly StringBuilder _pending = new();
    private int _pendingCount;
    private bool _exitHookRegistered;
    private const int FlushThreshold = 512;

    private void EnsureFlushAtExit()
    {
        if (_exitHookRegistered) return;
        _exitHookRegistered = true;
        AppDomain.CurrentDomain.ProcessExit += (_, _) => Flush();
    }

    /// <summary>Appends the pending answers to the cache file (also done past a threshold and at process exit).</summary>
    public void Flush()
    {
        lock (_diskLock)
        {
            if (_pending.Length == 0 || FilePath is null) return;
            var bytes = Encoding.UTF8.GetBytes(_pending.ToString());
            _pending.Clear();
            _pendingCount = 0;
            try
            {
                Directory.CreateDirectory(Path.GetDirectoryName(FilePath)!);
                using var stream = new FileStream(FilePath, FileMode.OpenOrCreate, FileAccess.ReadWrite, FileShare.ReadWrite | FileShare.Delete);
                // A line cut short by an earlier crash must not swallow these.
                if (stream.Length > 0)
                {
                    stream.Seek(-1, SeekOrigin.End);
                    if (stream.ReadByte() != '\n') stream.WriteByte((byte)'\n');
                }
                stream.Seek(0, SeekOrigin.End);
                stream.Write(bytes);
                stream.Flush();
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                Interlocked.Increment(ref _writeFailures);
            }
        }
    }

    private bool TryGetFromDisk(string key, out Scalar result)
    {
        result = Scalar.Zero;
        if (FilePath is null) return false;
        lock (_diskLock)
        {
            _disk ??= Load(FilePath);
            if (!_disk.TryGetValue(key, out var text)) return false;
            _disk.Remove(key);
            try
            {
                result = ScalarParser.ParseShared(text);
                return true;
            }
            // A value too large to build back term by term (it came from a product) is computed again.
            catch (Exception e) when (e is FormatException or ArgumentException or OverflowException or DivideByZeroException
                                          or Algebra.AlgebraException { ExceedsLimit: true })
            {
                return false;
            }
        }
    }

    private static Dictionary<string, string> Load(string path)
    {
        var entries = new Dictionary<string, string>(StringComparer.Ordinal);
        string content;
        try
        {
            using var stream = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.ReadWrite | FileShare.Delete);
            using var reader = new StreamReader(stream, new UTF8Encoding(false, throwOnInvalidBytes: false));
            content = reader.ReadToEnd();
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return entries;
        }
        foreach (var line in content.Split('\n'))
        {
            var parts = line.Split('\t');
            if (parts.Length != 3 || parts[2] != Checksum(parts[0], parts[1])) continue;
            entries[parts[0]] = parts[1];
        }
        return entries;
    }

    /// <summary>FNV-1a over key and result: detects torn and corrupted lines.</summary>
    private static string Checksum(string key, string result)
    {
        var hash = 14695981039346656037UL;
        foreach (var c in key) hash = (hash ^ c) * 1099511628211UL;
        hash = (hash ^ '\t') * 1099511628211UL;
        foreach (var c in result) hash = (hash ^ c) * 1099511628211UL;
        return hash.ToString("x16", CultureInfo.InvariantCulture);
    }
}
