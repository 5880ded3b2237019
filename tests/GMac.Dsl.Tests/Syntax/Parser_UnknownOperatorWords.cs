using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Syntax;

/// <summary>A word between two operands that is no product (`a meet b`) is named as an unknown operator, at the word.</summary>
public sealed class Parser_UnknownOperatorWords
{
    [Theory]
    [InlineData("y = a «meet» b;")]
    [InlineData("y = (a gp b) «wedge» (b op a);")]
    [InlineData("y = 2 «dot» a;")]
    public void An_unknown_word_between_operands_is_an_unknown_operator(string statement)
    {
        var d = MarkedSource.AssertSingle($$"""
            define macro M as
                inputs: { a : e3d.Vector; b : e3d.Vector }
                outputs: { y : e3d.Multivector }
                performs:
                    {{statement}}
            end macro
            """, "GMAC0001", DslSnippets.E3d);
        Assert.StartsWith("unknown operator '", d.Message);
        Assert.EndsWith("'; the products are gp, op, sp, lcp, rcp, fdp, hip, cp, acp, vee (and +, -, *, /, ^)", d.Message);
    }

    [Fact]
    public void A_statement_on_the_next_line_without_a_semicolon_is_still_a_statement()
    {
        var project = SingleFileProject.Bind("""
            define frame f as basis: {x, y} Euclidean end frame
            define macro M as
                inputs: { a : f.Multivector }
                outputs: { y : f.Multivector }
                performs:
                    t = a
                    y = t gp a
            end macro
            """);
        Assert.DoesNotContain(project.Diagnostics, d => d.IsError);
    }
}
