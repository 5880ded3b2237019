using System.Security.Cryptography;

namespace RayTracer.Util;

/// <summary>
/// Writes a file through a temporary sibling and a rename, so a failure never leaves a half-written file
/// and an existing file is replaced only by a complete one. The temporary name is hidden and random
/// (<c>.NAME.RANDOM.tmp</c>), so it never collides with a file of the user's.
/// </summary>
internal static class AtomicFile
{
    public static void Write(string path, ReadOnlySpan<byte> contents)
    {
        byte[] copy = contents.ToArray();
        Write(path, stream => stream.Write(copy));
    }

    public static void Write(string path, Action<Stream> write)
    {
        ArgumentNullException.ThrowIfNull(write);
        string full = Path.GetFullPath(path);
        string temp = TemporarySibling(full);
        bool created = false;
        try
        {
            // CreateNew: the temporary name must be ours alone, never an existing file.
            using (var stream = new FileStream(temp, FileMode.CreateNew, FileAccess.Write, FileShare.None, 1 << 16))
            {
                created = true;
                write(stream);
            }

            File.Move(temp, full, overwrite: true);
            created = false;
        }
        finally
        {
            if (created)
            {
                TryDelete(temp);
            }
        }
    }

    /// <summary>A hidden, randomly named file in the folder of <paramref name="full"/>.</summary>
    internal static string TemporarySibling(string full)
    {
        string directory = Path.GetDirectoryName(full) ?? throw new ArgumentException($"'{full}' names no file.", nameof(full));
        string random = Convert.ToHexStringLower(RandomNumberGenerator.GetBytes(8));
        return Path.Combine(directory, $".{Path.GetFileName(full)}.{random}.tmp");
    }

    private static void TryDelete(string temp)
    {
        try
        {
            File.Delete(temp);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // The original failure matters more than a leftover temporary file.
        }
    }
}
