using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Semantics;

/// <summary>Constant values that have no meaning (empty limits, division by zero, NaN) are errors when binding.</summary>
public sealed class Binder_ConstantValues
{
    [Fact]
    public void Class_binding_with_a_minimum_above_its_maximum_is_an_error_at_the_binding()
    {
        var d = MarkedSource.AssertSingle("""
            define binding «V» as
                use frame e3d
                bind { e1 : <x>; e2 : <y>; e3 : <z> }
                min { x : 5 }
                max { x : 2 }
            end binding
            """, "GMAC0125", DslSnippets.E3d);
        Assert.Contains("'x'", d.Message);
        Assert.Contains("5", d.Message);
        Assert.Contains("2", d.Message);
    }

    [Fact]
    public void Class_binding_with_consistent_limits_binds()
    {
        var project = DslProject.FromSources([("test.gmac", """
            define binding V as
                use frame e3d
                bind { e1 : <x>; e2 : <y>; e3 : <z> }
                min { x : 2 }
                max { x : 2 }
            end binding
            """), ("prelude.gmac", DslSnippets.E3d)]);
        Assert.DoesNotContain(project.Diagnostics, d => d.IsError);
    }

    [Fact]
    public void Constant_divided_by_zero_is_an_error_at_the_division()
    {
        var d = MarkedSource.AssertSingle("define constant e3d.Inf as multivector { e1 : «1/0» } end constant", "GMAC0131", DslSnippets.E3d);
        Assert.Contains("division by zero", d.Message);
    }

    [Fact]
    public void Macro_dividing_by_a_constant_zero_is_an_error_at_the_division()
    {
        MarkedSource.AssertSingle("""
            define macro M as
                inputs: { u : e3d.Vector }
                outputs: { w : e3d.Vector }
                performs:
                    w = «u / (2 - 2)»;
            end macro
            """, "GMAC0131", DslSnippets.E3d);
    }

    [Theory]
    [InlineData("sqrt(-4)", "NaN")]
    [InlineData("log(0)", "-infinity")]
    [InlineData("asin(2)", "NaN")]
    [InlineData("0^(-1)", "infinity")]
    public void Constant_without_a_finite_real_value_is_an_error_at_its_definition(string expression, string value)
    {
        var d = MarkedSource.AssertSingle($"define constant e3d.Bad as multivector {{ e1 : «{expression}» }} end constant", "GMAC0132", DslSnippets.E3d);
        Assert.Contains($"evaluates to {value}", d.Message);
    }

    [Fact]
    public void Constants_with_real_values_bind_without_errors()
    {
        var project = DslProject.FromSources([("test.gmac",
            "define constant e3d.Good as multivector { e1 : sqrt(4); e2 : log(1); e3 : asin(1) + 1/2 } end constant"),
            ("prelude.gmac", DslSnippets.E3d)]);
        Assert.DoesNotContain(project.Diagnostics, d => d.IsError);
    }
}
