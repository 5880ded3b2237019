namespace SafeFiles;

/// <summary>
/// Writes a program's output file without ever putting a regular file in place of something else:
/// a regular file (or a new one) is replaced atomically through <see cref="AtomicFile"/>, a FIFO is
/// written into (a reader waits at its other end), and a device, socket or directory, directly or
/// through a symbolic link, is refused and left as it is.
/// </summary>
public static class OutputFile
{
    /// <summary>Writes what <paramref name="write"/> puts in the stream to <paramref name="path"/>.</summary>
    /// <exception cref="IOException">The path names a special file other than a FIFO, or the write failed.</exception>
    /// <exception cref="UnauthorizedAccessException">The system refused the write.</exception>
    public static void Write(string path, Action<Stream> write)
    {
        ArgumentNullException.ThrowIfNull(write);
        switch (Describe(path))
        {
            case null:
                AtomicFile.Write(path, write);
                break;
            case "FIFO":
                using (var fifo = new FileStream(path, FileMode.Open, FileAccess.Write, FileShare.ReadWrite, 1 << 16))
                    write(fifo);
                break;
            case var kind:
                var through = new FileInfo(path).LinkTarget is null ? "" : " (through a symbolic link)";
                throw new IOException($"'{path}' is a {kind}{through}, not a regular file, and is left as it is");
        }
    }

    /// <summary>Writes <paramref name="contents"/>; see <see cref="Write(string, Action{Stream})"/>.</summary>
    public static void Write(string path, ReadOnlySpan<byte> contents)
    {
        var copy = contents.ToArray();
        Write(path, stream => stream.Write(copy));
    }

    /// <summary>
    /// What <paramref name="path"/> names, following symbolic links, finely enough to tell a FIFO from a
    /// device or a socket (<see cref="FileStat"/> says only "special"). Null for a regular file or a path that names nothing yet (both are written atomically); otherwise
    /// what it is, in words: "FIFO", "character device", "block device", "socket", "directory".
    /// </summary>
    public static string? Describe(string path)
    {
        if (FileStat.TypeBitsOf(path) is not { } type)
        {
            return FileStat.KindOf(path) switch
            {
                FileKind.Directory => "directory",
                FileKind.Special => "special file",
                _ => null,
            };
        }

        return type switch
        {
            0x8000 => null,
            0x4000 => "directory",
            0x1000 => "FIFO",
            0x2000 => "character device",
            0x6000 => "block device",
            0xC000 => "socket",
            _ => "special file",
        };
    }
}
