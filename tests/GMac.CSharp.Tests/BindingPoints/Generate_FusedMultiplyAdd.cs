using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>
/// <c>//GMac.Fma(true)</c> makes a region's code fuse products into sums; the code compiles where it
/// is written and gmac verify passes it. A line that is not <c>true</c> or <c>false</c>, or a second
/// Fma line, is an error at that line (file, line, column), and the file is left as it was.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_FusedMultiplyAdd : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private static string Source(string fmaLines) => $$"""
        public struct V3 { public double x, y, z; }

        public static class K
        {
            public static V3 Normal(V3 u, V3 v)
            {
                var w = new V3();
                #region GMac : NormalToVectors
                {{fmaLines}}
                //GMac.Bind("u", "Vector3D", u);
                //GMac.Bind("v", "Vector3D", v);
                //GMac.Bind("w", "Vector3D", w);
                #endregion
                return w;
            }
        }

        """;

    [Fact]
    public void An_fma_region_fuses_products_compiles_and_passes_verify()
    {
        var path = _temp.Write("K.cs", Source("//GMac.Fma(true);"));
        var (exit, output, err) = Tool.Generate([_temp.Path]);
        Assert.True(exit == 0, err + output);
        Assert.Contains("Math.FusedMultiplyAdd(", File.ReadAllText(path));
        var (verifyExit, verifyOut, verifyErr) = Tool.Verify(_temp.Path);
        Assert.True(verifyExit == 0, verifyErr + verifyOut);
    }

    [Fact]
    public void Without_the_line_or_with_false_the_code_is_unfused()
    {
        foreach (var line in new[] { "", "//GMac.Fma(false);" })
        {
            var path = _temp.Write("K.cs", Source(line));
            var (exit, output, err) = Tool.Generate([_temp.Path]);
            Assert.True(exit == 0, err + output);
            Assert.DoesNotContain("FusedMultiplyAdd", File.ReadAllText(path));
        }
    }

    [Theory]
    // The Fma line is line 9; column 9 is where its "//" starts.
    [InlineData("//GMac.Fma(\"yes\");", "(9,9): error GMAC0455", "GMac.Fma(\"yes\"): the argument must be true or false")]
    [InlineData("//GMac.Fma(1);", "(9,9): error GMAC0455", "GMac.Fma(1): the argument must be true or false")]
    [InlineData("//GMac.Fma(true);\n        //GMac.Fma(true);", "(10,9): error GMAC0455", "a second GMac.Fma line")]
    [InlineData("//GMac.Fma();", "(9,9): error GMAC0404", "GMac.Fma takes one argument, true or false, not 0")]
    public void A_bad_fma_line_is_an_error_at_its_line_and_the_file_stays(string lines, string position, string message)
    {
        var source = Source(lines);
        var path = _temp.Write("K.cs", source);
        var (exit, _, err) = Tool.Generate([_temp.Path]);
        Assert.Equal(1, exit);
        Assert.Contains($"K.cs{position}", err);
        Assert.Contains(message, err);
        Assert.Equal(source, File.ReadAllText(path));
    }
}
