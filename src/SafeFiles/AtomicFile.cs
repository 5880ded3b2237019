using System.Runtime.InteropServices;
using System.Security.Cryptography;

namespace SafeFiles;

/// <summary>
/// Replaces a file's content through a temporary sibling and an atomic rename, so a crash, a full
/// disk or an interrupt leaves either the old file or the new one, never half of one. A replaced
/// file keeps its permissions, its extended attributes and, where the system allows, its owner; a
/// symbolic link stays a link and its target gets the content. A file with several hard links is
/// rewritten in place instead, so that every name of it gets the content (see <see cref="OverwriteInPlace"/>).
/// Temporary names are hidden and random (<c>.NAME.RANDOM.tmp</c>), so they never collide with a
/// user's file or with another run's.
/// </summary>
public static class AtomicFile
{
    public const string TempSuffix = ".tmp";

    /// <summary>Temporary files older than this are left-overs of a killed run, not of one still writing.</summary>
    private static readonly TimeSpan StaleAge = TimeSpan.FromHours(1);

    // Guards the temporary files in flight, so an interrupt deletes exactly those and never one being renamed.
    private static readonly Lock Gate = new();
    private static readonly HashSet<string> Pending = new(StringComparer.Ordinal);
    private static bool _terminating;
    private static readonly List<PosixSignalRegistration> Signals = RegisterSignals();

    /// <summary>Writes <paramref name="contents"/> to <paramref name="path"/>.</summary>
    /// <exception cref="IOException">The file could not be written; it is left as it was.</exception>
    /// <exception cref="UnauthorizedAccessException">The system refused the write; the file is left as it was.</exception>
    public static void Write(string path, ReadOnlySpan<byte> contents)
    {
        var copy = contents.ToArray();
        Write(path, stream => stream.Write(copy));
    }

    /// <summary>Writes what <paramref name="write"/> puts in the stream; if it throws, the file is left as it was.</summary>
    public static void Write(string path, Action<Stream> write) => Write(path, write, expected: null);

    /// <summary>
    /// Writes <paramref name="contents"/> to <paramref name="path"/> only if the file still holds
    /// exactly <paramref name="expected"/>, what the caller read and derived the contents from: it is
    /// compared just before the rename, so an edit made meanwhile by another program is kept, and a
    /// file deleted meanwhile is not created again.
    /// </summary>
    /// <exception cref="FileChangedException">The file changed or was deleted since it was read; it is left as it is.</exception>
    /// <exception cref="IOException">The file could not be written; it is left as it was.</exception>
    /// <exception cref="UnauthorizedAccessException">The system refused the write; the file is left as it was.</exception>
    public static void Replace(string path, ReadOnlySpan<byte> contents, byte[] expected)
    {
        ArgumentNullException.ThrowIfNull(expected);
        var copy = contents.ToArray();
        Write(path, stream => stream.Write(copy), expected);
    }

    private static void Write(string path, Action<Stream> write, byte[]? expected)
    {
        ArgumentNullException.ThrowIfNull(write);
        lock (Gate)
        {
            // the process is about to end: start nothing it could leave half done
            if (_terminating) throw new IOException("the run was interrupted");
            var target = FinalTarget(path);
            var exists = File.Exists(target);
            if (expected is not null && !exists) throw new FileChangedException(target, deleted: true);
            if (exists) ThrowIfNotWritable(target);
            RemoveStaleTemps(target);
            var temp = CreateTemp(target, privateUntilRenamed: exists);
            try
            {
                using (var stream = new FileStream(temp, FileMode.Open, FileAccess.Write, FileShare.None, 1 << 16))
                {
                    write(stream);
                    stream.Flush(flushToDisk: true);
                }
                // a rename would give the other names of a hard-linked file nothing, so it is written in place
                var inPlace = exists && FileStat.LinkCountOf(target) > 1;
                if (exists && !inPlace && !OperatingSystem.IsWindows()) CopyOwnerAttributesAndMode(target, temp);
                if (expected is not null) ThrowIfChanged(target, expected);
                if (inPlace)
                {
                    OverwriteInPlace(temp, target);
                    Abandon(temp);
                }
                else
                {
                    File.Move(temp, target, overwrite: true);
                    Pending.Remove(temp);
                }
            }
            catch
            {
                // not pending any more: kept on purpose (see OverwriteInPlace)
                if (Pending.Contains(temp)) Abandon(temp);
                throw;
            }
        }
    }

    /// <summary>
    /// Throws unless <paramref name="target"/> holds exactly <paramref name="expected"/>. Another
    /// program could still write between this check and the rename that follows, but that window
    /// is microseconds, not the length of the caller's run.
    /// </summary>
    private static void ThrowIfChanged(string target, byte[] expected)
    {
        byte[] now;
        try
        {
            now = File.ReadAllBytes(target);
        }
        catch (Exception e) when (e is FileNotFoundException or DirectoryNotFoundException)
        {
            throw new FileChangedException(target, deleted: true);
        }
        if (!now.AsSpan().SequenceEqual(expected)) throw new FileChangedException(target, deleted: false);
    }

    /// <summary>
    /// Copies the finished temporary file into <paramref name="target"/> itself, keeping its inode
    /// and so every hard link, owner, mode and extended attribute. This is not atomic: if the copy
    /// fails, the old content is written back; if even that fails, the temporary file with the new
    /// content is kept and named in the error, so nothing is lost.
    /// </summary>
    private static void OverwriteInPlace(string temp, string target)
    {
        var old = File.ReadAllBytes(target);
        try
        {
            using var source = new FileStream(temp, FileMode.Open, FileAccess.Read, FileShare.Read);
            CopyInto(target, source);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            try
            {
                using var back = new MemoryStream(old, writable: false);
                CopyInto(target, back);
            }
            catch (Exception again) when (again is IOException or UnauthorizedAccessException)
            {
                Pending.Remove(temp); // keep it: it is the only whole copy of the new content
                throw new IOException($"'{target}' has several hard links and was being rewritten in place when this failed: {e.Message}; putting its old content back failed too ({again.Message}): the new content is in '{temp}'", e);
            }
            throw new IOException($"'{target}' has several hard links and could not be rewritten in place: {e.Message}; its old content was put back", e);
        }
    }

    private static void CopyInto(string target, Stream source)
    {
        using var stream = new FileStream(target, FileMode.Open, FileAccess.Write, FileShare.None, 1 << 16);
        source.CopyTo(stream);
        stream.SetLength(source.Length);
        stream.Flush(flushToDisk: true);
    }

    /// <summary>Writes <paramref name="bytes"/>; returns null on success, else why it could not (the file is then unchanged).</summary>
    public static string? TryWrite(string path, ReadOnlySpan<byte> bytes)
    {
        try
        {
            Write(path, bytes);
            return null;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return e.Message;
        }
    }

    /// <summary>The file a path finally names: the end of its chain of symbolic links, or the path itself.</summary>
    private static string FinalTarget(string path)
    {
        var info = new FileInfo(Path.GetFullPath(path));
        if (info.LinkTarget is null) return info.FullName;
        return info.ResolveLinkTarget(returnFinalTarget: true)?.FullName ?? info.FullName;
    }

    /// <summary>
    /// Asks the system whether the file may be written by opening it for writing (nothing is
    /// written): permission bits alone do not say, since root may write any file.
    /// </summary>
    private static void ThrowIfNotWritable(string target)
    {
        try
        {
            using var probe = File.OpenHandle(target, FileMode.Open, FileAccess.Write, FileShare.ReadWrite);
        }
        catch (UnauthorizedAccessException e)
        {
            throw new UnauthorizedAccessException($"the file '{target}' is read-only (permission denied)", e);
        }
        catch (IOException)
        {
            // held open elsewhere, say: the rename decides
        }
    }

    /// <summary>
    /// Creates an empty, uniquely named temporary sibling. When it will replace an existing file it
    /// is readable by its owner only until it takes that file's own permissions; a new file gets the
    /// system's default permissions, as any newly created file would.
    /// </summary>
    private static string CreateTemp(string target, bool privateUntilRenamed)
    {
        var folder = Path.GetDirectoryName(target) ?? throw new IOException($"'{target}' names no file");
        var name = Path.GetFileName(target);
        for (var attempt = 0; ; attempt++)
        {
            // random, not the process id: a pid repeats across runs (in a container, every run is pid 1)
            var temp = Path.Join(folder, $".{name}.{Convert.ToHexStringLower(RandomNumberGenerator.GetBytes(6))}{TempSuffix}");
            var options = new FileStreamOptions { Mode = FileMode.CreateNew, Access = FileAccess.Write, Share = FileShare.None };
            if (privateUntilRenamed && !OperatingSystem.IsWindows()) options.UnixCreateMode = UnixFileMode.UserRead | UnixFileMode.UserWrite;
            try
            {
                new FileStream(temp, options).Dispose();
            }
            catch (IOException) when (attempt < 3 && File.Exists(temp))
            {
                continue;
            }
            Pending.Add(temp);
            return temp;
        }
    }

    [System.Runtime.Versioning.UnsupportedOSPlatform("windows")]
    private static void CopyOwnerAttributesAndMode(string target, string temp)
    {
        // owner first: changing it clears set-user-id and set-group-id bits
        if (FileStat.OwnerOf(target) is { } owner && FileStat.OwnerOf(temp) != owner)
            FileStat.TryChangeOwner(temp, owner.User, owner.Group);
        // before the mode: an access-control list is an attribute, and setting it rewrites the group bits
        ExtendedAttributes.Copy(target, temp);
        File.SetUnixFileMode(temp, File.GetUnixFileMode(target));
    }

    private static void Abandon(string temp)
    {
        Pending.Remove(temp);
        try
        {
            File.Delete(temp);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // the original file is intact; a stray temporary file is the lesser problem
        }
    }

    /// <summary>Deletes temporary files of this writer for <paramref name="target"/> that a killed run left behind.</summary>
    private static void RemoveStaleTemps(string target)
    {
        var folder = Path.GetDirectoryName(target)!;
        var prefix = $".{Path.GetFileName(target)}.";
        try
        {
            foreach (var file in new DirectoryInfo(folder).EnumerateFiles($".*{TempSuffix}"))
            {
                if (!IsOurTemp(file.Name, prefix) || Pending.Contains(file.FullName)) continue;
                if (DateTime.UtcNow - file.LastWriteTimeUtc > StaleAge) file.Delete();
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // only tidying
        }
    }

    /// <summary>Exactly the names <see cref="CreateTemp"/> makes: the prefix, twelve lower-case hex digits, the suffix.</summary>
    private static bool IsOurTemp(string name, string prefix)
    {
        if (!name.StartsWith(prefix, StringComparison.Ordinal) || !name.EndsWith(TempSuffix, StringComparison.Ordinal)) return false;
        var random = name.AsSpan(prefix.Length, name.Length - prefix.Length - TempSuffix.Length);
        return random.Length == 12 && !random.ContainsAnyExcept("0123456789abcdef");
    }

    /// <summary>On an interrupt or a termination request, deletes the temporary files in flight before the process ends.</summary>
    private static List<PosixSignalRegistration> RegisterSignals()
    {
        var registrations = new List<PosixSignalRegistration>();
        foreach (var signal in new[] { PosixSignal.SIGINT, PosixSignal.SIGTERM, PosixSignal.SIGHUP, PosixSignal.SIGQUIT })
        {
            try
            {
                registrations.Add(PosixSignalRegistration.Create(signal, _ => Terminate()));
            }
            catch (PlatformNotSupportedException)
            {
                // not on this system
            }
        }
        return registrations;
    }

    /// <summary>
    /// Deletes every temporary file in flight and refuses new ones. A write under way holds the
    /// gate, so it finishes (renamed, or deleted on failure) before this runs.
    /// </summary>
    private static void Terminate()
    {
        lock (Gate)
        {
            _terminating = true;
            foreach (var temp in Pending.ToList()) Abandon(temp);
        }
    }
}
