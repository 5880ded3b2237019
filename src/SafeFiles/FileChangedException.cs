namespace SafeFiles;

/// <summary>
/// A file was changed or deleted by someone else after the caller read it, so replacing it would
/// lose their work: <see cref="AtomicFile.Replace"/> left it as it now is.
/// </summary>
public sealed class FileChangedException : IOException
{
    public FileChangedException(string path, bool deleted)
        : base(deleted ? $"'{path}' was deleted after it was read" : $"'{path}' was changed after it was read")
    {
        Path = path;
        Deleted = deleted;
    }

    /// <summary>The file (the end of its chain of symbolic links).</summary>
    public string Path { get; }

    /// <summary>True when the file no longer exists (it is not created again).</summary>
    public bool Deleted { get; }
}
