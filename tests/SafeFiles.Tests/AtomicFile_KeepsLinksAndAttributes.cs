using System.Runtime.InteropServices;
using SafeFiles.Tests.Support;

namespace SafeFiles.Tests;

/// <summary>
/// A replaced file stays the file it was: every hard link of it sees the new content, and its
/// extended attributes are kept.
/// </summary>
public sealed class AtomicFile_KeepsLinksAndAttributes : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("atomic-file-").FullName;

    public void Dispose() => Directory.Delete(_dir, true);

    private string[] Names() => [.. Directory.GetFiles(_dir).Select(f => Path.GetFileName(f)).Order()];

    [Fact]
    public void Both_names_of_a_hard_linked_file_get_the_new_content()
    {
        if (OperatingSystem.IsWindows()) return;
        var first = Path.Combine(_dir, "first.cs");
        var second = Path.Combine(_dir, "second.cs");
        File.WriteAllText(first, "an old text longer than the new one");
        File.SetUnixFileMode(first, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.GroupRead);
        Assert.True(Link(first, second) == 0, Marshal.GetPInvokeErrorMessage(Marshal.GetLastPInvokeError()));

        AtomicFile.Write(second, "new"u8);

        Assert.Equal("new", File.ReadAllText(first));
        Assert.Equal("new", File.ReadAllText(second));
        Assert.Equal(2u, FileStat.LinkCountOf(first));
        Assert.Equal(UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.GroupRead, File.GetUnixFileMode(first));
        Assert.Equal(["first.cs", "second.cs"], Names());
    }

    [Fact]
    public void A_hard_linked_file_changed_since_it_was_read_is_left_as_it_is()
    {
        if (OperatingSystem.IsWindows()) return;
        var first = Path.Combine(_dir, "first.cs");
        var second = Path.Combine(_dir, "second.cs");
        File.WriteAllText(first, "old");
        Assert.True(Link(first, second) == 0);
        var read = File.ReadAllBytes(first);
        File.AppendAllText(second, " edited");

        Assert.Throws<FileChangedException>(() => AtomicFile.Replace(first, "new"u8, read));

        Assert.Equal("old edited", File.ReadAllText(first));
        Assert.Equal(["first.cs", "second.cs"], Names());
    }

    [UserAttributesFact]
    public void User_extended_attributes_are_kept()
    {
        var path = Path.Combine(_dir, "tagged.cs");
        File.WriteAllText(path, "old");
        Assert.Null(ExtendedAttributes.TrySet(path, "user.origin", "https://example.org/a.cs"u8.ToArray()));
        Assert.Null(ExtendedAttributes.TrySet(path, "user.empty", []));

        AtomicFile.Write(path, "new"u8);

        Assert.Equal("new", File.ReadAllText(path));
        Assert.Equal(["user.empty", "user.origin"], ExtendedAttributes.List(path).Where(n => n.StartsWith("user.", StringComparison.Ordinal)).Order());
        Assert.Equal("https://example.org/a.cs"u8.ToArray(), ExtendedAttributes.Get(path, "user.origin"));
        Assert.Equal(Array.Empty<byte>(), ExtendedAttributes.Get(path, "user.empty"));
    }

    [DllImport("libc", EntryPoint = "link", SetLastError = true)]
    private static extern int Link([MarshalAs(UnmanagedType.LPUTF8Str)] string existing, [MarshalAs(UnmanagedType.LPUTF8Str)] string newName);
}
