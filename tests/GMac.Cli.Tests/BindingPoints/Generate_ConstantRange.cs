using GMac.CSharp.BindingPoints;
using GMac.CSharp.Tests.Support;
using GMac.Dsl;

namespace GMac.Cli.Tests.BindingPoints;

/// <summary>
/// A constant beyond the scalar type's range (10^39 > 3.4·10^38 for float, 10^400 for double) has no
/// C# literal: it is a positioned error, not code that prints <c>Infinity</c> and does not compile.
/// </summary>
public sealed class Generate_ConstantRange : IDisposable
{
    private const string Dsl = """
        define frame e3d as basis: {e1, e2, e3} Euclidean end frame
        define subspace e3d.scalars as basis {1} end subspace
        define multivector class e3d.Scalar as scalars end multivector class
        define macro Big as
            inputs: { a : e3d.Scalar }
            outputs: { w : e3d.Scalar }
            performs:
                w = a * 10^39;
        end macro
        define macro Huge as
            inputs: { a : e3d.Scalar }
            outputs: { w : e3d.Scalar }
            performs:
                w = a * 10^400;
        end macro
        """;

    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private static string Source(string macro, string typeLine) => $$"""
        public static class K
        {
            public static double F(double x)
            {
                double y = 0;
                  #region GMac : {{macro}}
                  {{typeLine}}
                  //GMac.Bind("a.1", "<x>");
                  //GMac.Bind("w.1", "<y>");
                  #endregion
                return y;
            }
        }
        """;

    [Theory]
    [InlineData("Big", "//GMac.Type(\"float\");", "float", "1E+39")]
    [InlineData("Huge", "", "double", "1E+400")]
    public void A_constant_beyond_the_scalar_range_is_an_error_at_the_binding_point(string macro, string typeLine, string type, string constant)
    {
        var dsl = _temp.Write(Path.Combine("dsl", "k.gmac"), Dsl);
        var text = Source(macro, typeLine);
        var code = _temp.Write("K.cs", text);
        var context = new GenerationContext(DslProject.Load(Path.GetDirectoryName(dsl)!), Path.Combine(_temp.Path, "cache"));

        var (exit, _, err) = Tool.Generate([code], context: context);

        Assert.Equal(1, exit);
        // The #region is on line 6, column 11 of K.cs.
        Assert.StartsWith($"{code}(6,11): error GMAC0315: macro '{macro}' cannot be generated in {type}: the constant {constant} is outside the range of {type}", err.Trim());
        Assert.Equal(text, File.ReadAllText(code));
    }

    [Fact]
    public void The_same_constant_in_double_is_written_and_compiles()
    {
        var dsl = _temp.Write(Path.Combine("dsl", "k.gmac"), Dsl);
        var code = _temp.Write("K.cs", Source("Big", ""));
        var context = new GenerationContext(DslProject.Load(Path.GetDirectoryName(dsl)!), Path.Combine(_temp.Path, "cache"));

        var (exit, _, err) = Tool.Generate([code], context: context);

        Assert.True(exit == 0, err);
        Assert.Empty(CSharpCompile.Errors(code));
    }

    [Fact]
    public void Show_reports_it_at_the_macro()
    {
        _temp.Write("k.gmac", Dsl);
        var (exit, output, err) = Tool.Run("show", "Huge", "--dsl", _temp.Path, "--cache", Path.Combine(_temp.Path, "cache"));

        Assert.Equal(1, exit);
        Assert.Equal("", output);
        Assert.StartsWith($"{Path.Combine(_temp.Path, "k.gmac")}(10,14): error GMAC0315: ", err.Trim());
    }
}
