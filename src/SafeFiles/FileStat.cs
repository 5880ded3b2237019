using System.Runtime.InteropServices;

namespace SafeFiles;

/// <summary>
/// The file type, owner and link count of a path, which .NET does not expose: <c>statx</c> on Linux (one
/// struct layout on every architecture), <c>stat</c> on macOS, attributes elsewhere.
/// </summary>
public static class FileStat
{
    private const int TypeMask = 0xF000;
    private const int TypeRegular = 0x8000;
    private const int TypeDirectory = 0x4000;

    /// <summary>The kind of <paramref name="path"/>, following symbolic links.</summary>
    public static FileKind KindOf(string path)
    {
        if (Query(path) is { } status)
        {
            return (status.Mode & TypeMask) switch
            {
                TypeRegular => FileKind.Regular,
                TypeDirectory => FileKind.Directory,
                _ => FileKind.Special,
            };
        }
        if (OperatingSystem.IsLinux() || OperatingSystem.IsMacOS()) return FileKind.Unknown;
        if (Directory.Exists(path)) return FileKind.Directory;
        return File.Exists(path) ? FileKind.Regular : FileKind.Unknown;
    }

    /// <summary>
    /// The file-type bits of <paramref name="path"/>'s mode (<c>st_mode &amp; S_IFMT</c>: 0x1000 FIFO,
    /// 0x2000 character device, 0x4000 directory, 0x6000 block device, 0x8000 regular, 0xC000 socket),
    /// following symbolic links; null where the platform does not say or nothing is there.
    /// </summary>
    public static int? TypeBitsOf(string path) => Query(path) is { } status ? status.Mode & TypeMask : null;

    /// <summary>The owning user and group of <paramref name="path"/>; null where the platform does not say.</summary>
    public static (uint User, uint Group)? OwnerOf(string path) =>
        Query(path) is { } status ? (status.User, status.Group) : null;

    /// <summary>
    /// How many hard links (names) the file <paramref name="path"/> has, following symbolic links;
    /// null where the platform does not say.
    /// </summary>
    public static uint? LinkCountOf(string path) => Query(path)?.Links;

    /// <summary>Gives <paramref name="path"/> the owner and group; false when the system refuses (only root may give files away).</summary>
    public static bool TryChangeOwner(string path, uint user, uint group)
    {
        if (!OperatingSystem.IsLinux() && !OperatingSystem.IsMacOS()) return false;
        try
        {
            return Chown(path, user, group) == 0;
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
        {
            return false;
        }
    }

    private readonly record struct Status(int Mode, uint User, uint Group, uint Links);

    private static Status? Query(string path)
    {
        try
        {
            if (OperatingSystem.IsLinux()) return QueryLinux(path);
            if (OperatingSystem.IsMacOS()) return QueryMac(path);
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
        {
            // an unusual C library: callers fall back to what .NET can tell
        }
        return null;
    }

    // struct statx (linux/stat.h): stx_mask u32 @0, stx_nlink u32 @16, stx_uid u32 @20, stx_gid u32 @24, stx_mode u16 @28; 256 bytes in all.
    private static Status? QueryLinux(string path)
    {
        const int currentDirectory = -100; // AT_FDCWD
        const uint wanted = 0x1 | 0x4 | 0x8 | 0x10; // STATX_TYPE | STATX_NLINK | STATX_UID | STATX_GID
        var buffer = new byte[256];
        if (StatX(currentDirectory, path, 0, wanted, buffer) != 0) return null;
        if ((MemoryMarshal.Read<uint>(buffer) & 0x1) == 0) return null;
        var status = Read(buffer, modeAt: 28, userAt: 20, groupAt: 24);
        return status with { Links = MemoryMarshal.Read<uint>(buffer.AsSpan(16)) };
    }

    // struct stat with 64-bit inodes (the only one on arm64, "stat$INODE64" on x64):
    // st_dev i32 @0, st_mode u16 @4, st_nlink u16 @6, st_ino u64 @8, st_uid u32 @16, st_gid u32 @20.
    private static Status? QueryMac(string path)
    {
        var buffer = new byte[512];
        var result = RuntimeInformation.ProcessArchitecture == Architecture.X64 ? MacStatX64(path, buffer) : MacStat(path, buffer);
        return result != 0 ? null : Read(buffer, modeAt: 4, userAt: 16, groupAt: 20) with { Links = MemoryMarshal.Read<ushort>(buffer.AsSpan(6)) };
    }

    // The kernel fills the struct in the machine's own byte order.
    private static Status Read(ReadOnlySpan<byte> b, int modeAt, int userAt, int groupAt) =>
        new(MemoryMarshal.Read<ushort>(b[modeAt..]), MemoryMarshal.Read<uint>(b[userAt..]), MemoryMarshal.Read<uint>(b[groupAt..]), Links: 1);

    [DllImport("libc", EntryPoint = "statx", SetLastError = true)]
    private static extern int StatX(int directory, [MarshalAs(UnmanagedType.LPUTF8Str)] string path, int flags, uint mask, [Out] byte[] buffer);

    [DllImport("libc", EntryPoint = "stat", SetLastError = true)]
    private static extern int MacStat([MarshalAs(UnmanagedType.LPUTF8Str)] string path, [Out] byte[] buffer);

    [DllImport("libc", EntryPoint = "stat$INODE64", SetLastError = true)]
    private static extern int MacStatX64([MarshalAs(UnmanagedType.LPUTF8Str)] string path, [Out] byte[] buffer);

    [DllImport("libc", EntryPoint = "chown", SetLastError = true)]
    private static extern int Chown([MarshalAs(UnmanagedType.LPUTF8Str)] string path, uint user, uint group);
}
