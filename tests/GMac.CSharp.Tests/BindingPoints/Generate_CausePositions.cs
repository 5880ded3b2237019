using GMac.CSharp.BindingPoints;
using GMac.CSharp.Tests.Support;
using GMac.Dsl;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>A binding point that fails inside its macro is reported at the DSL line at fault, naming the binding point.</summary>
public sealed class Generate_CausePositions : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    [Fact]
    public void Division_that_is_zero_for_the_bindings_is_reported_at_the_dsl_with_the_binding_point_appended()
    {
        var dsl = _temp.Write(Path.Combine("dsl", "div.gmac"), """
            define frame e3d as basis: {e1, e2, e3} Euclidean end frame
            define subspace e3d.vectors as basis {e1, e2, e3} end subspace
            define multivector class e3d.Vector as vectors end multivector class
            define macro DivZero as
                inputs: { x : e3d.Vector }
                outputs: { w : e3d.Vector }
                performs:
                    w = x / (x.<e1> - x.<e1>);
            end macro
            """);
        var text = """
            public static class K
            {
                public static void F(double a, ref double b)
                {
                    #region GMac : DivZero
                    //GMac.Bind("x.e1", "<a>");
                    //GMac.Bind("x.e2", "0");
                    //GMac.Bind("x.e3", "0");
                    //GMac.Bind("w.e1", "<b>");
                    #endregion
                }
            }
            """;
        var code = _temp.Write("K.cs", text);
        var context = new GenerationContext(DslProject.Load(Path.GetDirectoryName(dsl)!), Path.Combine(_temp.Path, "cache"));

        var (exit, _, err) = Tool.Generate([code], context: context);

        Assert.Equal(1, exit);
        // Line 8 of div.gmac, the division after "w = "; the region is on line 5 of K.cs.
        Assert.Equal(
            $"{dsl}(8,13): error GMAC0313: macro 'DivZero' cannot be generated for these bindings: in 'x / (x.<e1> - x.<e1>)': division by zero: " +
            $"the divisor simplifies to zero for these bindings (binding point at {code}(5,1))",
            err.Trim());
        Assert.Equal(text, File.ReadAllText(code));
    }
}
