using System.Runtime.InteropServices;
using System.Security.Cryptography;
using GMac.Dsl.Files;

namespace GMac.Cli.BindingPoints;

/// <summary>
/// Replaces a file's content through a temporary file in the same folder and an atomic rename,
/// so a crash or a full disk leaves either the old file or the new one, never half of one. The
/// new file keeps the old one's permissions and, where the system allows, its owner; a symbolic
/// link stays a link and its target gets the content.
/// </summary>
internal static class SafeFileWriter
{
    public const string TempSuffix = ".gmac-tmp";

    /// <summary>Temporary files older than this are left-overs of a killed run, not of one still writing.</summary>
    private static readonly TimeSpan StaleAge = TimeSpan.FromHours(1);

    // Guards the temporary files in flight, so an interrupt deletes exactly those and never one being renamed.
    private static readonly Lock Gate = new();
    private static readonly HashSet<string> Pending = new(StringComparer.Ordinal);
    private static bool _terminating;
    private static readonly List<PosixSignalRegistration> Signals = RegisterSignals();

    /// <summary>Writes <paramref name="bytes"/>; returns null on success, else why it could not.</summary>
    public static string? Replace(string path, byte[] bytes)
    {
        lock (Gate)
        {
            // the process is about to end: start nothing it could leave half done
            if (_terminating) return "the run was interrupted";
            string target;
            try
            {
                target = FinalTarget(path);
            }
            catch (IOException e)
            {
                return e.Message;
            }
            var exists = File.Exists(target);
            if (exists && WhyNotWritable(target) is { } refused) return refused;
            RemoveStaleTemps(target);
            string? temp = null;
            try
            {
                temp = CreateTemp(target, bytes);
                if (exists && !OperatingSystem.IsWindows()) CopyOwnerAndMode(target, temp);
                File.Move(temp, target, overwrite: true);
                Pending.Remove(temp);
                return null;
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                if (temp is not null) Abandon(temp);
                return e.Message;
            }
        }
    }

    /// <summary>The file a path finally names: the end of its chain of symbolic links, or the path itself.</summary>
    private static string FinalTarget(string path)
    {
        var info = new FileInfo(path);
        if (info.LinkTarget is null) return info.FullName;
        return info.ResolveLinkTarget(returnFinalTarget: true)?.FullName ?? info.FullName;
    }

    /// <summary>
    /// Asks the system whether the file may be written by opening it for writing (nothing is
    /// written): permission bits alone do not say, since root may write any file.
    /// </summary>
    private static string? WhyNotWritable(string target)
    {
        try
        {
            using var probe = File.OpenHandle(target, FileMode.Open, FileAccess.Write, FileShare.ReadWrite);
            return null;
        }
        catch (UnauthorizedAccessException)
        {
            return "the file is read-only (permission denied)";
        }
        catch (IOException)
        {
            // held open elsewhere, say: the rename decides
            return null;
        }
    }

    private static string CreateTemp(string target, byte[] bytes)
    {
        var folder = Path.GetDirectoryName(target)!;
        var name = Path.GetFileName(target);
        for (var attempt = 0; ; attempt++)
        {
            // random, not the process id: a pid repeats across runs (in a container, every run is pid 1)
            var temp = Path.Join(folder, $".{name}.{Convert.ToHexStringLower(RandomNumberGenerator.GetBytes(6))}{TempSuffix}");
            var options = new FileStreamOptions { Mode = FileMode.CreateNew, Access = FileAccess.Write, Share = FileShare.None };
            // only the owner may read it until it gets the target's own permissions
            if (!OperatingSystem.IsWindows()) options.UnixCreateMode = UnixFileMode.UserRead | UnixFileMode.UserWrite;
            FileStream stream;
            try
            {
                stream = new FileStream(temp, options);
            }
            catch (IOException) when (attempt < 3 && File.Exists(temp))
            {
                continue;
            }
            Pending.Add(temp);
            using (stream)
            {
                stream.Write(bytes);
                stream.Flush(flushToDisk: true);
            }
            return temp;
        }
    }

    [System.Runtime.Versioning.UnsupportedOSPlatform("windows")]
    private static void CopyOwnerAndMode(string target, string temp)
    {
        // owner first: changing it clears set-user-id and set-group-id bits
        if (FileStat.OwnerOf(target) is { } owner && FileStat.OwnerOf(temp) != owner)
            FileStat.TryChangeOwner(temp, owner.User, owner.Group);
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

    /// <summary>Deletes this tool's temporary files for <paramref name="target"/> that a killed run left behind.</summary>
    private static void RemoveStaleTemps(string target)
    {
        var folder = Path.GetDirectoryName(target)!;
        var prefix = $".{Path.GetFileName(target)}.";
        try
        {
            foreach (var file in new DirectoryInfo(folder).EnumerateFiles($"*{TempSuffix}"))
            {
                if (!file.Name.StartsWith(prefix, StringComparison.Ordinal) || Pending.Contains(file.FullName)) continue;
                if (DateTime.UtcNow - file.LastWriteTimeUtc > StaleAge) file.Delete();
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // only tidying
        }
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
