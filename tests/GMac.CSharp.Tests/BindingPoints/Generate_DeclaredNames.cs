using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>
/// A region that binds only inputs declares its outputs under default names (<c>w_e1</c>): where
/// such a name is already declared (by a parameter, a local, another region of the same block),
/// the region is refused before anything is written; where C# allows it, the code compiles.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_DeclaredNames : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private const string Region = """
        #region GMac : GetNormalToVectors
                //GMac.Bind("u.e1", "<x>");
                //GMac.Bind("u.e2", "<y>");
                //GMac.Bind("u.e3", "<z>");
                //GMac.Bind("v.e1", "<y>");
                //GMac.Bind("v.e2", "<z>");
                //GMac.Bind("v.e3", "<x>");
                #endregion
        """;

    private static string File(string method) => $$"""
        namespace Sample;

        public static class K
        {
        {{method.Replace("REGION", Region, StringComparison.Ordinal)}}
        }
        """;

    private (int Exit, string Err, string Text, string Path) Generate(string method)
    {
        var text = File(method);
        var path = _temp.Write("K.cs", text);
        var (exit, _, err) = Tool.Generate([path]);
        return (exit, err, text, path);
    }

    /// <summary>The 1-based line of the <paramref name="n"/>-th (0-based) <c>#region</c> of the text.</summary>
    private static int RegionLine(string text, int n) =>
        text.Split('\n').Select((l, i) => (l, i)).Where(x => x.l.Contains("#region GMac", StringComparison.Ordinal)).ElementAt(n).i + 1;

    private static int LineOf(string text, string part) => Array.FindIndex(text.Split('\n'), l => l.Contains(part, StringComparison.Ordinal)) + 1;

    [Fact]
    public void Two_inputs_only_regions_in_one_block_are_refused_at_the_second()
    {
        var (exit, err, text, path) = Generate("""
                public static double M(double x, double y, double z)
                {
                    REGION
                    var first = w_e1;
                    REGION
                    return first + w_e1;
                }
            """);

        Assert.Equal(1, exit);
        Assert.Contains($"K.cs({RegionLine(text, 1)},9): error GMAC0432: the code of 'GetNormalToVectors' declares 'w_e1', which the code of the region of line {RegionLine(text, 0)}", err, StringComparison.Ordinal);
        Assert.Equal(text, System.IO.File.ReadAllText(path));
    }

    [Fact]
    public void A_parameter_with_a_default_output_name_is_refused()
    {
        var (exit, err, text, path) = Generate("""
                public static double M(double x, double y, double z, double w_e2)
                {
                    REGION
                    return w_e1;
                }
            """);

        Assert.Equal(1, exit);
        Assert.Contains($"K.cs({RegionLine(text, 0)},9): error GMAC0432: the code of 'GetNormalToVectors' declares 'w_e2', but the parameter 'w_e2' of line {LineOf(text, "double w_e2)")} is already declared where it goes", err, StringComparison.Ordinal);
        Assert.Equal(text, System.IO.File.ReadAllText(path));
    }

    [Fact]
    public void A_local_of_an_inner_block_with_a_default_output_name_is_refused()
    {
        var (exit, err, text, _) = Generate("""
                public static double M(double x, double y, double z)
                {
                    REGION
                    for (var i = 0; i < 2; i++) { var w_e3 = i; x += w_e3; }
                    return w_e1;
                }
            """);

        Assert.Equal(1, exit);
        Assert.Contains($"error GMAC0432: the code of 'GetNormalToVectors' declares 'w_e3', but the local 'w_e3' of line {LineOf(text, "var w_e3")} ", err, StringComparison.Ordinal);
    }

    [Fact]
    public void Regions_in_sibling_blocks_and_a_lambda_may_reuse_the_names_and_compile()
    {
        var (exit, err, _, path) = Generate("""
                public static double M(bool c, double x, double y, double z, double w_e1)
                {
                    if (c)
                    {
                        REGION
                        return w_e1;
                    }
                    else
                    {
                        REGION
                        return w_e2;
                    }
                }

                public static System.Func<double> L(double x, double y, double z)
                {
                    var w_e1 = 1.0;
                    return () =>
                    {
                        REGION
                        return w_e1;
                    };
                }
            """.Replace("double w_e1)", "double w)", StringComparison.Ordinal));

        Assert.True(exit == 0, err);
        Assert.Equal(3, System.IO.File.ReadAllText(path).Split("double w_e1 = ").Length - 1);
        Assert.Empty(CSharpCompile.Errors(path));
    }
}
