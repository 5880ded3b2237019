using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>
/// A region's code is statements: a region where statements cannot stand is refused at its
/// <c>#region</c>, the file left alone; one between statements (of a block, a switch section, a
/// lambda) is generated and compiles.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_RegionPlacement : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    /// <summary>An inputs-only binding point: its code declares <c>w_e1</c>… and reads x, y and z.</summary>
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

    private static string File(string members) => $$"""
        namespace Sample;

        public static class K
        {
            private static double x, y, z;

        {{members}}
        }
        """;

    [Theory]
    [InlineData("among members", "REGION    public static void M() { }")]
    [InlineData("argument list", "    public static void M() { System.Console.WriteLine(\"{0}\",\nREGION    x); }")]
    [InlineData("switch expression arm", "    public static int M(int q) => q switch\n    {\n        1 => 2,\nREGION        _ => 0,\n    };")]
    [InlineData("expression body", "    public static double M() =>\nREGION        x;")]
    [InlineData("attribute list", "    [\nREGION    System.Obsolete]\n    public static void M() { }")]
    [InlineData("if without braces", "    public static void M(bool c)\n    {\n        if (c)\nREGION        System.Console.WriteLine();\n    }")]
    [InlineData("inside a declaration", "    public static void M()\n    {\n        double d = x\nREGION        ;\n    }")]
    public void A_region_where_statements_cannot_stand_is_refused_at_its_region_line(string place, string members)
    {
        var text = File(members.Replace("REGION", Region, StringComparison.Ordinal));
        var path = _temp.Write("K.cs", text);
        var lines = text.Split('\n');
        var line = Array.FindIndex(lines, l => l.Contains("#region GMac", StringComparison.Ordinal)) + 1;
        var column = lines[line - 1].IndexOf('#', StringComparison.Ordinal) + 1;

        var (exit, _, err) = Tool.Generate([path]);

        Assert.True(exit == 1, place);
        Assert.Contains($"K.cs({line},{column}): error GMAC0431: ", err, StringComparison.Ordinal);
        Assert.Equal(text, System.IO.File.ReadAllText(path));
    }

    [Fact]
    public void Regions_in_a_block_a_switch_section_and_a_lambda_body_are_generated_and_compile()
    {
        var text = File("""
                public static double InBlock()
                {
            REGION        return w_e1;
                }

                public static double InSection(int q)
                {
                    switch (q)
                    {
                        case 1:
            REGION            return w_e2;
                        default:
                            return 0;
                    }
                }

                public static System.Func<double> InLambda() => () =>
                {
            REGION        return w_e3;
                };
            """.Replace("REGION", Region, StringComparison.Ordinal));
        var path = _temp.Write("K.cs", text);

        var (exit, _, err) = Tool.Generate([path]);

        Assert.True(exit == 0, err);
        var after = System.IO.File.ReadAllText(path);
        Assert.Equal(3, after.Split("double w_e1 = ").Length - 1);
        Assert.Empty(CSharpCompile.Errors(path));
    }
}
