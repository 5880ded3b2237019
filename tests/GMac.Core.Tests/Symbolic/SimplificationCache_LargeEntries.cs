using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

/// <summary>
/// A simplified value with more terms than a sum may be built with term by term is written to disk
/// like any other and read back whole, not refused as too large (which failed the binding point).
/// </summary>
public sealed class SimplificationCache_LargeEntries : IDisposable
{
    private readonly string _directory = Path.Combine(Path.GetTempPath(), "gmac-cache-test-" + Guid.NewGuid().ToString("N"));

    public void Dispose()
    {
        if (Directory.Exists(_directory)) Directory.Delete(_directory, recursive: true);
    }

    [Fact]
    public void An_entry_longer_than_the_sum_limit_reads_back()
    {
        var large = Scalar.FromTerms(Enumerable.Range(0, Scalar.MaxTerms + 1).Select(i => Scalar.Variable($"x{i}").Terms[0]));
        var first = new SimplificationCache(_directory);
        first.Add("large", large);
        first.Flush();

        var second = new SimplificationCache(_directory);
        Assert.True(second.TryGet("large", out var read));
        Assert.Equal(large, read);
    }
}
