namespace SafeFiles.Tests;

public sealed class AtomicFile_Writes : IDisposable
{
    private readonly string _dir = Path.Combine(Path.GetTempPath(), "atomic-file-" + Guid.NewGuid().ToString("N"));

    public AtomicFile_Writes() => Directory.CreateDirectory(_dir);

    public void Dispose() => Directory.Delete(_dir, true);

    private string[] Names() => [.. Directory.GetFiles(_dir).Select(f => Path.GetFileName(f)).Order()];

    [Fact]
    public void A_user_file_named_like_the_old_temporary_is_left_alone()
    {
        var target = Path.Combine(_dir, "keep.png");
        File.WriteAllText(target + ".tmp", "mine");
        File.WriteAllText(target + "." + Environment.ProcessId + ".tmp", "mine too");

        AtomicFile.Write(target, "new"u8);

        Assert.Equal("new", File.ReadAllText(target));
        Assert.Equal("mine", File.ReadAllText(target + ".tmp"));
        Assert.Equal("mine too", File.ReadAllText(target + "." + Environment.ProcessId + ".tmp"));
        Assert.Equal(3, Names().Length);
    }

    [Fact]
    public void The_temporary_file_is_a_hidden_randomly_named_sibling()
    {
        var target = Path.Combine(_dir, "keep.png");
        var seen = new List<string>();
        for (var i = 0; i < 2; i++)
        {
            AtomicFile.Write(target, stream =>
            {
                var temp = Assert.Single(Names(), name => name != "keep.png");
                Assert.StartsWith(".keep.png.", temp);
                Assert.EndsWith(".tmp", temp);
                seen.Add(temp);
                stream.WriteByte(1);
            });
        }

        Assert.NotEqual(seen[0], seen[1]);
        Assert.Equal(["keep.png"], Names());
    }

    [Fact]
    public void A_failed_write_keeps_the_old_file_and_leaves_nothing_behind()
    {
        var target = Path.Combine(_dir, "mesh.ply");
        File.WriteAllText(target, "old");

        Assert.Throws<InvalidOperationException>(() => AtomicFile.Write(target, stream =>
        {
            stream.WriteByte(42);
            throw new InvalidOperationException("disk full");
        }));

        Assert.Equal("old", File.ReadAllText(target));
        Assert.Equal(["mesh.ply"], Names());
    }

    [Fact]
    public void A_new_file_gets_the_permissions_any_new_file_gets()
    {
        if (OperatingSystem.IsWindows()) return;
        var plain = Path.Combine(_dir, "plain.bin");
        File.WriteAllBytes(plain, [1]);
        var written = Path.Combine(_dir, "written.bin");

        AtomicFile.Write(written, [1]);

        Assert.Equal(File.GetUnixFileMode(plain), File.GetUnixFileMode(written));
    }

    [Theory]
    [InlineData(UnixFileMode.UserRead | UnixFileMode.UserWrite)]
    [InlineData(UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute | UnixFileMode.GroupRead | UnixFileMode.GroupExecute | UnixFileMode.OtherRead | UnixFileMode.OtherExecute)]
    public void A_replaced_file_keeps_its_permissions(UnixFileMode mode)
    {
        if (OperatingSystem.IsWindows()) return;
        var target = Path.Combine(_dir, "script.sh");
        File.WriteAllText(target, "old");
        File.SetUnixFileMode(target, mode);

        AtomicFile.Write(target, "new"u8);

        Assert.Equal("new", File.ReadAllText(target));
        Assert.Equal(mode, File.GetUnixFileMode(target));
    }

    [Fact]
    public void A_symbolic_link_stays_a_link_and_its_target_gets_the_content()
    {
        var target = Path.Combine(_dir, "real.txt");
        File.WriteAllText(target, "old");
        var link = Path.Combine(_dir, "link.txt");
        File.CreateSymbolicLink(link, target);

        AtomicFile.Write(link, "new"u8);

        Assert.Equal(target, new FileInfo(link).LinkTarget);
        Assert.Equal("new", File.ReadAllText(target));
        Assert.Equal(["link.txt", "real.txt"], Names());
    }

    [Fact]
    public void Try_write_says_why_it_could_not_write_and_creates_nothing()
    {
        var missingFolder = Path.Combine(_dir, "no", "such", "folder", "out.png");
        var why = AtomicFile.TryWrite(missingFolder, [1, 2, 3]);
        Assert.NotNull(why);
        Assert.Empty(Names());
    }
}
