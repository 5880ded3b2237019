using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.Commands;

/// <summary><c>gmac check</c> on DSL folders holding things other than plain files.</summary>
public sealed class CheckCommand_SpecialFiles : IDisposable
{
    private const string Frame = "define frame e2d as basis: {e1, e2} Euclidean end frame\n";

    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    [UnixFact]
    public void A_fifo_named_like_a_dsl_file_is_skipped_with_a_warning()
    {
        _temp.Write("dsl/frames.gmac", Frame);
        var fifo = Path.Combine(_temp.Path, "dsl/x.gmac");
        Fifo.Create(fifo);

        var run = Task.Run(() => Tool.Run("check", "--dsl", Path.Combine(_temp.Path, "dsl")));
        // a safety net only: the check reads nothing from the FIFO and ends at once
        var finished = run.Wait(TimeSpan.FromMinutes(1));
        if (!finished) Fifo.Release(fifo);

        Assert.True(finished, "check blocked on the FIFO");
        var (exit, output, err) = run.Result;
        Assert.True(exit == 0, err);
        Assert.Contains("1 file(s)", output, StringComparison.Ordinal);
        Assert.Matches(@"x\.gmac\(1,1\): warning GMAC0203: not a regular file", err);
    }

    [Fact]
    public void A_link_to_an_ancestor_folder_reads_each_file_once()
    {
        _temp.Write("dsl/frames.gmac", Frame);
        Directory.CreateDirectory(Path.Combine(_temp.Path, "dsl/more"));
        Directory.CreateSymbolicLink(Path.Combine(_temp.Path, "dsl/more/loop"), "..");

        var (exit, output, err) = Tool.Run("check", "--dsl", Path.Combine(_temp.Path, "dsl"));

        Assert.True(exit == 0, err);
        Assert.Contains("1 file(s)", output, StringComparison.Ordinal);
        Assert.DoesNotContain("GMAC0102", err, StringComparison.Ordinal);
    }
}
