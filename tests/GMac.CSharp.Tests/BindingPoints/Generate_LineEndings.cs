using System.Text.RegularExpressions;
using GMac.CSharp.BindingPoints;
using GMac.CSharp.Tests.Support;
using GMac.Dsl;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>Generated lines, and the text of output blocks in them, end as the file's own lines do.</summary>
[Collection(SharedDslCollection.Name)]
public sealed partial class Generate_LineEndings : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    [Fact]
    public void A_file_with_only_cr_line_endings_gets_only_cr()
    {
        var text = StaleKernel.Text.Replace("\n", "\r", StringComparison.Ordinal);
        var path = _temp.Write("Normals.cs", text);

        var (exit, _, err) = Tool.Generate([path]);

        Assert.True(exit == 0, err);
        var after = File.ReadAllText(path);
        Assert.Contains(StaleKernel.GeneratedMarker, after, StringComparison.Ordinal);
        Assert.DoesNotContain("\n", after, StringComparison.Ordinal);
        var (again, output, _) = Tool.Generate([path]);
        Assert.Equal(0, again);
        Assert.Contains("0 file(s) changed", output, StringComparison.Ordinal);
        var (check, _, checkErr) = Tool.Generate([path], check: true);
        Assert.True(check == 0, checkErr);
    }

    [Fact]
    public void Output_block_text_written_with_lf_goes_into_a_crlf_file_with_crlf()
    {
        var dsl = _temp.Write(Path.Combine("dsl", "copy.gmac"), """
            define frame e3d as basis: {e1, e2, e3} Euclidean end frame
            define subspace e3d.vectors as basis {e1, e2, e3} end subspace
            define multivector class e3d.Vector as vectors end multivector class
            define macro Twice as
                inputs: { u : e3d.Vector }
                outputs: { w : e3d.Vector }
                performs:
                    w = 2 * u;
                    output {
                        // twice <u.e1>
                        // and more
                    };
            end macro
            """.Replace("\r\n", "\n", StringComparison.Ordinal));
        var text = """
            public static class K
            {
                public static void F(double a, ref double b)
                {
                    #region GMac : Twice
                    //GMac.Bind("u.e1", "<a>");
                    //GMac.Bind("u.e2", "0");
                    //GMac.Bind("u.e3", "0");
                    //GMac.Bind("w.e1", "<b>");
                    #endregion
                }
            }
            """.Replace("\r\n", "\n", StringComparison.Ordinal).Replace("\n", "\r\n", StringComparison.Ordinal);
        var path = _temp.Write("K.cs", text);
        var context = new GenerationContext(DslProject.Load(Path.GetDirectoryName(dsl)!), cacheDirectory: null);

        var (exit, _, err) = Tool.Generate([path], context: context);

        Assert.True(exit == 0, err);
        var after = File.ReadAllText(path);
        Assert.Contains("// and more", after, StringComparison.Ordinal);
        Assert.DoesNotMatch(BareLineFeed(), after);
        Assert.DoesNotMatch(BareCarriageReturn(), after);
    }

    [GeneratedRegex("(?<!\r)\n")]
    private static partial Regex BareLineFeed();

    [GeneratedRegex("\r(?!\n)")]
    private static partial Regex BareCarriageReturn();
}
