namespace SafeFiles.Tests;

/// <summary>
/// <see cref="AtomicFile.Replace"/> writes only over the content the caller read: an edit or a
/// deletion by another program since then is kept.
/// </summary>
public sealed class AtomicFile_ReplacesOnlyWhatWasRead : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("atomic-file-").FullName;

    public void Dispose() => Directory.Delete(_dir, true);

    private string[] Names() => [.. Directory.GetFiles(_dir).Select(f => Path.GetFileName(f)).Order()];

    [Fact]
    public void A_file_that_still_holds_what_was_read_is_replaced()
    {
        var path = Path.Combine(_dir, "A.cs");
        File.WriteAllText(path, "old");
        var read = File.ReadAllBytes(path);

        AtomicFile.Replace(path, "new"u8, read);

        Assert.Equal("new", File.ReadAllText(path));
        Assert.Equal(["A.cs"], Names());
    }

    [Fact]
    public void A_file_changed_since_it_was_read_is_left_as_it_is()
    {
        var path = Path.Combine(_dir, "A.cs");
        File.WriteAllText(path, "old");
        var read = File.ReadAllBytes(path);
        File.AppendAllText(path, " and a line typed meanwhile");

        var e = Assert.Throws<FileChangedException>(() => AtomicFile.Replace(path, "new"u8, read));

        Assert.False(e.Deleted);
        Assert.Equal("old and a line typed meanwhile", File.ReadAllText(path));
        Assert.Equal(["A.cs"], Names());
    }

    [Fact]
    public void A_file_deleted_since_it_was_read_is_not_created_again()
    {
        var path = Path.Combine(_dir, "A.cs");
        File.WriteAllText(path, "old");
        var read = File.ReadAllBytes(path);
        File.Delete(path);

        var e = Assert.Throws<FileChangedException>(() => AtomicFile.Replace(path, "new"u8, read));

        Assert.True(e.Deleted);
        Assert.Empty(Names());
    }

    [Fact]
    public void Through_a_symbolic_link_the_target_is_compared()
    {
        var target = Path.Combine(_dir, "real.cs");
        File.WriteAllText(target, "old");
        var link = Path.Combine(_dir, "link.cs");
        File.CreateSymbolicLink(link, target);
        var read = File.ReadAllBytes(link);
        File.WriteAllText(target, "edited");

        Assert.Throws<FileChangedException>(() => AtomicFile.Replace(link, "new"u8, read));

        Assert.Equal("edited", File.ReadAllText(target));
        Assert.Equal(target, new FileInfo(link).LinkTarget);
    }
}
