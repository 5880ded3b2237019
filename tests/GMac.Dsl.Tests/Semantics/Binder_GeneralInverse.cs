using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Semantics;

/// <summary>general_inverse has closed forms up to 5 dimensions: in a larger frame it is GMAC0155 at the call.</summary>
public sealed class Binder_GeneralInverse
{
    [Fact]
    public void General_inverse_in_six_dimensions_is_an_error_at_the_call()
    {
        var d = MarkedSource.AssertSingle("""
            define macro M as
                inputs: { a : f6.Multivector }
                outputs: { y : f6.Multivector }
                performs:
                    y = «general_inverse(a)»;
            end macro
            """, "GMAC0155", "define frame f6 as basis: {e1, e2, e3, e4, e5, e6} Euclidean end frame");
        Assert.Contains("up to 5 dimensions", d.Message);
        Assert.Contains("'f6' has 6", d.Message);
        Assert.Contains("inverse(A)", d.Message);
    }

    [Fact]
    public void General_inverse_in_five_dimensions_binds()
    {
        var project = SingleFileProject.Bind("""
            define frame f5 as basis: {e1, e2, e3, e4, e5} Euclidean end frame
            define macro M as
                inputs: { a : f5.Multivector }
                outputs: { y : f5.Multivector }
                performs:
                    y = general_inverse(a);
            end macro
            """);
        Assert.DoesNotContain(project.Diagnostics, d => d.IsError);
    }
}
