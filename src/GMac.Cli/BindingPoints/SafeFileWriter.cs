namespace GMac.Cli.BindingPoints;

/// <summary>
/// Replaces a file's content through a temporary file in the same folder and an atomic rename,
/// so a crash or a full disk leaves either the old file or the new one, never half of one.
/// </summary>
internal static class SafeFileWriter
{
    /// <summary>Writes <paramref name="bytes"/>; returns null on success, else why it could not.</summary>
    public static string? Replace(string path, byte[] bytes)
    {
        var info = new FileInfo(path);
        if (info.Exists && info.IsReadOnly) return "the file is read-only";
        var temp = Path.Combine(info.DirectoryName ?? ".", $".{info.Name}.{Environment.ProcessId}.gmac-tmp");
        try
        {
            using (var stream = new FileStream(temp, FileMode.CreateNew, FileAccess.Write, FileShare.None))
            {
                stream.Write(bytes);
                stream.Flush(flushToDisk: true);
            }
            File.Move(temp, path, overwrite: true);
            return null;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            try
            {
                if (File.Exists(temp)) File.Delete(temp);
            }
            catch (Exception cleanup) when (cleanup is IOException or UnauthorizedAccessException)
            {
                // the original file is intact; a stray temp file is the lesser problem
            }
            return e.Message;
        }
    }
}
