using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.Commands;

/// <summary><c>gmac show --fma</c> prints fused multiply–adds; without it the code is unfused.</summary>
public sealed class ShowCommand_Fma
{
    private static string Dsl => SharedDsl.DslDirectory;

    [Theory]
    [InlineData("double", "Math.FusedMultiplyAdd(")]
    [InlineData("float", "MathF.FusedMultiplyAdd(")]
    [InlineData("Vector512<double>", "Vector512.FusedMultiplyAdd(")]
    [InlineData("Vector128<float>", "Vector128.FusedMultiplyAdd(")]
    public void Show_with_fma_fuses_products_into_sums(string scalar, string call)
    {
        var (exit, output, err) = Tool.Run("show", "NormalToVectors", "--dsl", Dsl, "--scalar", scalar, "--fma");
        Assert.True(exit == 0, err);
        Assert.Contains(call, output);
        (exit, output, err) = Tool.Run("show", "NormalToVectors", "--dsl", Dsl, "--scalar", scalar);
        Assert.True(exit == 0, err);
        Assert.DoesNotContain("FusedMultiplyAdd", output);
    }
}
