using System.Runtime.InteropServices;
using System.Text;

namespace SafeFiles;

/// <summary>
/// A file's extended attributes (<c>user.*</c> and the others on Linux, every name on macOS),
/// which .NET does not expose: a file replaced through a new temporary file would otherwise lose
/// them. Symbolic links are followed. Where the platform or the file system has none, a file has none.
/// </summary>
public static class ExtendedAttributes
{
    private const int RangeError = 34; // ERANGE (Linux and macOS): the value grew since its size was asked

    /// <summary>The names of the attributes of <paramref name="path"/>; empty where unsupported.</summary>
    /// <exception cref="IOException">The file's attributes cannot be listed (it is missing, say).</exception>
    public static IReadOnlyList<string> List(string path)
    {
        if (!IsSupportedPlatform) return [];
        var names = Query(path, null, (p, _, buffer, size) => OperatingSystem.IsMacOS() ? MacList(p, buffer, size, 0) : LinuxList(p, buffer, size));
        if (names is null) return [];
        return Encoding.UTF8.GetString(names).Split('\0', StringSplitOptions.RemoveEmptyEntries);
    }

    /// <summary>The value of the attribute <paramref name="name"/>; null when the file does not have it.</summary>
    /// <exception cref="IOException">The attribute cannot be read.</exception>
    public static byte[]? Get(string path, string name)
    {
        if (!IsSupportedPlatform) return null;
        return Query(path, name, (p, n, buffer, size) => OperatingSystem.IsMacOS() ? MacGet(p, n!, buffer, size, 0, 0) : LinuxGet(p, n!, buffer, size));
    }

    /// <summary>Sets the attribute; null on success, else the system's reason.</summary>
    public static string? TrySet(string path, string name, byte[] value)
    {
        ArgumentNullException.ThrowIfNull(value);
        if (!IsSupportedPlatform) return "extended attributes are not supported on this system";
        try
        {
            var result = OperatingSystem.IsMacOS()
                ? MacSet(path, name, value, (nuint)value.Length, 0, 0)
                : LinuxSet(path, name, value, (nuint)value.Length, 0);
            return result == 0 ? null : Marshal.GetPInvokeErrorMessage(Marshal.GetLastPInvokeError());
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
        {
            return "extended attributes are not supported by this C library";
        }
    }

    /// <summary>
    /// Gives <paramref name="to"/> every attribute of <paramref name="from"/>. On Linux only the
    /// <c>user.*</c> attributes must be copied: the others (security labels, ACLs, trusted
    /// attributes) need privileges and are copied where the system allows.
    /// </summary>
    /// <exception cref="IOException">An attribute that must be copied could not be.</exception>
    public static void Copy(string from, string to)
    {
        foreach (var name in List(from))
        {
            if (Get(from, name) is not { } value) continue;
            if (TrySet(to, name, value) is { } why && MustCopy(name))
                throw new IOException($"cannot keep the extended attribute '{name}' of '{from}': {why}");
        }
    }

    private static bool MustCopy(string name) => OperatingSystem.IsLinux() && name.StartsWith("user.", StringComparison.Ordinal);

    private static bool IsSupportedPlatform => OperatingSystem.IsLinux() || OperatingSystem.IsMacOS();

    private delegate nint Call(string path, string? name, byte[]? buffer, nuint size);

    /// <summary>Asks for the size, then the bytes (again if the value grew in between); null when there is nothing.</summary>
    private static byte[]? Query(string path, string? name, Call call)
    {
        try
        {
            for (var attempt = 0; ; attempt++)
            {
                var size = call(path, name, null, 0);
                if (size < 0) return Missing(path, name);
                var buffer = new byte[size];
                if (size == 0) return buffer;
                var read = call(path, name, buffer, (nuint)size);
                if (read >= 0) return buffer[..(int)read];
                if (Marshal.GetLastPInvokeError() == RangeError && attempt < 3) continue;
                return Missing(path, name);
            }
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
        {
            return null;
        }
    }

    /// <summary>After a failed call: null when the attribute (or attribute support) is absent, else an exception.</summary>
    private static byte[]? Missing(string path, string? name)
    {
        var error = Marshal.GetLastPInvokeError();
        // no such attribute (ENODATA on Linux, ENOATTR on macOS), or none on this file system (ENOTSUP, EOPNOTSUPP)
        var absent = OperatingSystem.IsMacOS() ? error is 93 or 45 or 102 : error is 61 or 95;
        if (absent) return null;
        throw new IOException($"cannot read the extended attributes{(name is null ? "" : $" ('{name}')")} of '{path}': {Marshal.GetPInvokeErrorMessage(error)}");
    }

    [DllImport("libc", EntryPoint = "listxattr", SetLastError = true)]
    private static extern nint LinuxList([MarshalAs(UnmanagedType.LPUTF8Str)] string path, byte[]? list, nuint size);

    [DllImport("libc", EntryPoint = "getxattr", SetLastError = true)]
    private static extern nint LinuxGet([MarshalAs(UnmanagedType.LPUTF8Str)] string path, [MarshalAs(UnmanagedType.LPUTF8Str)] string name, byte[]? value, nuint size);

    [DllImport("libc", EntryPoint = "setxattr", SetLastError = true)]
    private static extern int LinuxSet([MarshalAs(UnmanagedType.LPUTF8Str)] string path, [MarshalAs(UnmanagedType.LPUTF8Str)] string name, byte[] value, nuint size, int flags);

    [DllImport("libc", EntryPoint = "listxattr", SetLastError = true)]
    private static extern nint MacList([MarshalAs(UnmanagedType.LPUTF8Str)] string path, byte[]? list, nuint size, int options);

    [DllImport("libc", EntryPoint = "getxattr", SetLastError = true)]
    private static extern nint MacGet([MarshalAs(UnmanagedType.LPUTF8Str)] string path, [MarshalAs(UnmanagedType.LPUTF8Str)] string name, byte[]? value, nuint size, uint position, int options);

    [DllImport("libc", EntryPoint = "setxattr", SetLastError = true)]
    private static extern int MacSet([MarshalAs(UnmanagedType.LPUTF8Str)] string path, [MarshalAs(UnmanagedType.LPUTF8Str)] string name, byte[] value, nuint size, uint position, int options);
}
