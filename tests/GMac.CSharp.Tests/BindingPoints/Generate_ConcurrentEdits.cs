using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>
/// A file that another program (an editor saving, a build) changes or deletes while gmac generates
/// it keeps what that program did: gmac writes a file only if it still holds what gmac read. The
/// race is made deterministic by editing the file just before gmac would write it.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_ConcurrentEdits : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private const string UserLine = "// saved by the editor while gmac ran\n";

    [Fact]
    public void A_file_edited_during_the_run_keeps_the_edit_and_is_reported()
    {
        var path = _temp.Write("code/Normals.cs", StaleKernel.Text);

        var (exit, _, err) = Tool.Generate([Path.Combine(_temp.Path, "code")], beforeWrite: p =>
        {
            if (p == path) File.AppendAllText(p, UserLine);
        });

        Assert.Equal(1, exit);
        Assert.Equal(StaleKernel.Text + UserLine, File.ReadAllText(path));
        // reported at the binding point's #region (line 8, indented by 8)
        Assert.Matches(@"Normals\.cs\(8,9\): error GMAC0406: the file was changed while gmac generated it", err);

        // the edit is not taken for generated output: the next run generates the file
        var (again, _, againErr) = Tool.Generate([Path.Combine(_temp.Path, "code")]);
        Assert.True(again == 0, againErr);
        var text = File.ReadAllText(path);
        Assert.Contains(StaleKernel.GeneratedMarker, text, StringComparison.Ordinal);
        Assert.EndsWith(UserLine, text, StringComparison.Ordinal);
    }

    [Fact]
    public void A_file_deleted_during_the_run_is_not_created_again_and_the_other_files_are_written()
    {
        var deleted = _temp.Write("code/Deleted.cs", StaleKernel.Text);
        var other = _temp.Write("code/Other.cs", StaleKernel.Text);

        var (exit, _, err) = Tool.Generate([Path.Combine(_temp.Path, "code")], beforeWrite: p =>
        {
            if (p == deleted) File.Delete(p);
        });

        Assert.Equal(1, exit);
        Assert.False(File.Exists(deleted));
        Assert.Matches(@"Deleted\.cs\(8,9\): error GMAC0406: the file was deleted while gmac generated it; it is not created again", err);
        Assert.Contains(StaleKernel.GeneratedMarker, File.ReadAllText(other), StringComparison.Ordinal);
    }

    [Fact]
    public void A_file_replaced_with_the_same_bytes_during_the_run_is_written()
    {
        var path = _temp.Write("code/Normals.cs", StaleKernel.Text);

        // an editor that saves without changes, through its own temporary file and rename
        var (exit, _, err) = Tool.Generate([Path.Combine(_temp.Path, "code")], beforeWrite: p =>
        {
            var saved = p + ".saving";
            File.WriteAllText(saved, StaleKernel.Text);
            File.Move(saved, p, overwrite: true);
        });

        Assert.True(exit == 0, err);
        Assert.Contains(StaleKernel.GeneratedMarker, File.ReadAllText(path), StringComparison.Ordinal);
    }
}
