using System.Text.RegularExpressions;
using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.Verification;

/// <summary>
/// <c>gmac verify</c> on every binding point of the repository: the generated code, compiled in
/// memory, agrees with the numeric engine on random inputs.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Verify_RepositoryBindingPoints
{
    [Theory]
    [InlineData("samples/QuickStart", 3)]
    [InlineData("src/Twister", 1)]
    [InlineData("src/RayTracer/Kernels", 1)]
    public void Every_region_passes(string folder, int minimumRegions)
    {
        var (exit, output, err) = Tool.Verify(Path.Combine(SharedDsl.RepositoryRoot, folder));
        Assert.True(exit == 0, err + output);
        var summary = Regex.Match(output, @"gmac verify: (\d+) region\(s\), (\d+) passed, 0 problem\(s\)");
        Assert.True(summary.Success, output);
        Assert.True(int.Parse(summary.Groups[1].Value) >= minimumRegions, output);
        Assert.Equal(summary.Groups[1].Value, summary.Groups[2].Value);
    }

    [Fact]
    public void Benchmark_folder_verifies_at_least_one_binding_point()
    {
        var (exit, output, err) = Tool.Verify(Path.Combine(SharedDsl.RepositoryRoot, "bench"));
        Assert.True(exit == 0, err + output);
        var summary = Regex.Match(output, @"gmac verify: (\d+) region\(s\), (\d+) passed, 0 problem\(s\)");
        Assert.True(summary.Success, output);
        Assert.True(int.Parse(summary.Groups[1].Value) >= 1, output);
        Assert.Equal(summary.Groups[1].Value, summary.Groups[2].Value);
    }
}
