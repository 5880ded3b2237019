using GMac.Dsl.Generation;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Generation;

/// <summary>
/// An expansion too large to evaluate symbolically is refused early with GMAC0314 at its statement,
/// and statements that reach no output are not evaluated at all, however large they would be.
/// </summary>
public sealed class MacroCodeGenerator_SizeBudget
{
    // (seven terms)^16 expands to 74,613 terms through a product of 9 million term products:
    // minutes without a limit; the limit trips after a few thousand.
    private const string Huge = "(u.<e1> + u.<e2> + u.<e3> + v.<e1> + v.<e2> + v.<e3> + 1)^16";

    private static GenerationOutcome Generate(string performs)
    {
        var generator = new MacroCodeGenerator(SingleFileProject.Bind(DslSnippets.E3d + $$"""

            define macro M as
                inputs: { u : e3d.Vector; v : e3d.Vector }
                outputs: { w : e3d.Vector; s : e3d.Scalar }
                performs:
            {{performs}}
            end macro
            """));
        return generator.Generate("M", generator.DefaultBindings("M"));
    }

    /// <summary>The line of a statement in the file Generate builds: after the prelude and the four lines heading the macro.</summary>
    private static int StatementLine(int index) => DslSnippets.E3d.Split('\n').Length + 5 + index;

    [Fact]
    public void A_power_too_large_to_expand_is_refused_at_its_statement()
    {
        var outcome = Generate($"w = u;\ns = {Huge};");

        var error = Assert.Single(outcome.Errors);
        Assert.Equal("GMAC0314", error.Code);
        Assert.Contains("term products, more than the limit", error.Message);
        var at = Assert.IsType<Dsl.Diagnostics.SourceSpan>(error.Cause);
        Assert.Equal(("test.gmac", StatementLine(1), 1), (at.FilePath, at.Line, at.Column));
    }

    [Fact]
    public void Temporaries_that_reach_no_output_are_not_evaluated()
    {
        // t1 is read, but only by t2, which nothing reads: neither is expanded.
        var outcome = Generate($"t1 = {Huge};\nt2 = t1 + u.<e1>;\nw = u;\ns = u sp v;");

        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        Assert.Equal(4, outcome.Result!.Block.Outputs.Count());
    }
}
