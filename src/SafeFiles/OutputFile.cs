using System.Runtime.InteropServices;

namespace SafeFiles;

/// <summary>
/// Writes a program's output file without ever putting a regular file in place of something else:
/// a regular file (or a new one) is replaced atomically through <see cref="AtomicFile"/>, a FIFO is
/// written into (a reader waits at its other end), and a device, socket or directory, directly or
/// through a symbolic link, is refused and left as it is.
/// </summary>
public static class OutputFile
{
    private const int TypeMask = 0xF000;

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
        int? mode = null;
        try
        {
            mode = OperatingSystem.IsLinux() ? LinuxMode(path) : OperatingSystem.IsMacOS() ? MacMode(path) : null;
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
        {
            // an unusual C library: fall back to what SafeFiles can tell
        }

        if (mode is null)
        {
            return FileStat.KindOf(path) switch
            {
                FileKind.Directory => "directory",
                FileKind.Special => "special file",
                _ => null,
            };
        }

        return (mode & TypeMask) switch
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

    // struct statx: stx_mask u32 @0, stx_mode u16 @28 (the same on every architecture).
    private static int? LinuxMode(string path)
    {
        const int currentDirectory = -100; // AT_FDCWD
        const uint typeWanted = 0x1; // STATX_TYPE
        var buffer = new byte[256];
        if (StatX(currentDirectory, path, 0, typeWanted, buffer) != 0 || (MemoryMarshal.Read<uint>(buffer) & typeWanted) == 0)
        {
            return null;
        }

        return MemoryMarshal.Read<ushort>(buffer.AsSpan(28));
    }

    // struct stat with 64-bit inodes: st_mode u16 @4.
    private static int? MacMode(string path)
    {
        var buffer = new byte[512];
        int result = RuntimeInformation.ProcessArchitecture == Architecture.X64 ? MacStatX64(path, buffer) : MacStat(path, buffer);
        return result != 0 ? null : MemoryMarshal.Read<ushort>(buffer.AsSpan(4));
    }

    [DllImport("libc", EntryPoint = "statx", SetLastError = true)]
    private static extern int StatX(int directory, [MarshalAs(UnmanagedType.LPUTF8Str)] string path, int flags, uint mask, [Out] byte[] buffer);

    [DllImport("libc", EntryPoint = "stat", SetLastError = true)]
    private static extern int MacStat([MarshalAs(UnmanagedType.LPUTF8Str)] string path, [Out] byte[] buffer);

    [DllImport("libc", EntryPoint = "stat$INODE64", SetLastError = true)]
    private static extern int MacStatX64([MarshalAs(UnmanagedType.LPUTF8Str)] string path, [Out] byte[] buffer);
}
