using System.Runtime.Versioning;
using GMac.CSharp.BindingPoints;
using GMac.CSharp.Tests.Support;
using SafeFiles;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>
/// A rewritten file is the same file as before in every way but its content: links stay links
/// (hard links too), permissions, owner and extended attributes are kept, and no temporary file of an earlier run gets in the way.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_FileSafety : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private string Code => Directory.CreateDirectory(Path.Combine(_temp.Path, "code")).FullName;

    private static void AssertGenerated(string path)
    {
        var text = File.ReadAllText(path);
        Assert.Contains(StaleKernel.GeneratedMarker, text, StringComparison.Ordinal);
        Assert.DoesNotContain(StaleKernel.StaleLine, text, StringComparison.Ordinal);
    }

    [Fact]
    public void A_symbolic_link_stays_a_link_and_its_target_gets_the_code()
    {
        var target = _temp.Write("elsewhere/Normals.cs", StaleKernel.Text);
        var link = Path.Combine(Code, "Normals.cs");
        File.CreateSymbolicLink(link, Path.GetRelativePath(Code, target));

        var (exit, _, err) = Tool.Generate([Code]);

        Assert.True(exit == 0, err);
        Assert.Equal(Path.GetRelativePath(Code, target), new FileInfo(link).LinkTarget);
        AssertGenerated(target);
        Assert.Empty(Directory.GetFiles(_temp.Path, ".*" + AtomicFile.TempSuffix, SearchOption.AllDirectories));
    }

    [UnsupportedOSPlatform("windows")]
    [UnixFact]
    public void Permissions_are_kept()
    {
        var modes = new Dictionary<string, UnixFileMode>
        {
            ["Private.cs"] = UnixFileMode.UserRead | UnixFileMode.UserWrite,
            ["Script.cs"] = UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute
                | UnixFileMode.GroupRead | UnixFileMode.GroupExecute | UnixFileMode.OtherRead | UnixFileMode.OtherExecute,
        };
        foreach (var (name, mode) in modes) File.SetUnixFileMode(_temp.Write($"code/{name}", StaleKernel.Text), mode);

        var (exit, _, err) = Tool.Generate([Code]);

        Assert.True(exit == 0, err);
        foreach (var (name, mode) in modes)
        {
            var path = Path.Combine(Code, name);
            AssertGenerated(path);
            Assert.Equal(mode, File.GetUnixFileMode(path));
        }
    }

    [UnsupportedOSPlatform("windows")]
    [UnixFact(asRoot: true)]
    public void Root_writes_a_file_of_another_user_and_keeps_its_owner()
    {
        const uint nobody = 65534;
        var path = _temp.Write("code/Theirs.cs", StaleKernel.Text);
        Assert.True(FileStat.TryChangeOwner(path, nobody, nobody));
        // 644: only its owner has the write bit, yet root may write it
        File.SetUnixFileMode(path, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.GroupRead | UnixFileMode.OtherRead);

        var (exit, _, err) = Tool.Generate([Code]);

        Assert.True(exit == 0, err);
        AssertGenerated(path);
        Assert.Equal((nobody, nobody), FileStat.OwnerOf(path));
        Assert.Equal(UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.GroupRead | UnixFileMode.OtherRead, File.GetUnixFileMode(path));
    }

    [UnsupportedOSPlatform("windows")]
    [UnixFact(asOtherUser: true)]
    public void A_file_the_system_will_not_let_us_write_is_refused_and_left_alone()
    {
        var path = _temp.Write("code/ReadOnly.cs", StaleKernel.Text);
        File.SetUnixFileMode(path, UnixFileMode.UserRead | UnixFileMode.GroupRead | UnixFileMode.OtherRead);

        var (exit, _, err) = Tool.Generate([Code]);

        Assert.Equal(1, exit);
        Assert.Matches(@"ReadOnly\.cs\(8,9\): error GMAC0406: cannot write the generated code: the file is read-only", err);
        Assert.Equal(StaleKernel.Text, File.ReadAllText(path));
    }

    [UnsupportedOSPlatform("windows")]
    [UnixFact]
    public void A_file_with_two_hard_links_gets_the_code_under_both_names()
    {
        var path = _temp.Write("code/Normals.cs", StaleKernel.Text);
        // the other name lies outside the generated folder, as a shared file linked into a project would
        var other = Path.Combine(_temp.Path, "Shared.cs");
        HardLink.Create(path, other);

        var (exit, _, err) = Tool.Generate([Code]);

        Assert.True(exit == 0, err);
        AssertGenerated(path);
        Assert.Equal(File.ReadAllBytes(path), File.ReadAllBytes(other));
        Assert.Equal(2u, FileStat.LinkCountOf(path));
        Assert.Empty(Directory.GetFiles(_temp.Path, ".*" + AtomicFile.TempSuffix, SearchOption.AllDirectories));
    }

    [UnsupportedOSPlatform("windows")]
    [UnixFact(userAttributes: true)]
    public void Extended_attributes_are_kept()
    {
        var path = _temp.Write("code/Normals.cs", StaleKernel.Text);
        var value = "reviewed by Ada"u8.ToArray();
        Assert.Null(ExtendedAttributes.TrySet(path, "user.gmac.test", value));

        var (exit, _, err) = Tool.Generate([Code]);

        Assert.True(exit == 0, err);
        AssertGenerated(path);
        Assert.Equal(value, ExtendedAttributes.Get(path, "user.gmac.test"));
    }

    [Fact]
    public void Temporary_files_left_by_a_killed_run_are_removed_and_user_files_are_not()
    {
        var path = _temp.Write("code/Normals.cs", StaleKernel.Text);
        // what an interrupted run left behind a day ago
        var leftOver = _temp.Write($"code/.Normals.cs.00112233aabb{AtomicFile.TempSuffix}", "half of a file");
        File.SetLastWriteTimeUtc(leftOver, DateTime.UtcNow.AddDays(-1));
        // one that a concurrent run may still be writing
        var recent = _temp.Write($"code/.Normals.cs.0123456789ab{AtomicFile.TempSuffix}", "being written");
        // old files of the user's that merely look similar
        var users = new[] { $"code/.Normals.cs.backup{AtomicFile.TempSuffix}", $"code/.Normals.cs.{Environment.ProcessId}{AtomicFile.TempSuffix}", "code/Normals.cs.tmp" }
            .Select(name => _temp.Write(name, "the user's")).ToArray();
        foreach (var file in users) File.SetLastWriteTimeUtc(file, DateTime.UtcNow.AddDays(-1));

        var (exit, _, err) = Tool.Generate([Code]);

        Assert.True(exit == 0, err);
        AssertGenerated(path);
        Assert.False(File.Exists(leftOver));
        Assert.True(File.Exists(recent));
        Assert.All(users, file => Assert.Equal("the user's", File.ReadAllText(file)));
    }
}
