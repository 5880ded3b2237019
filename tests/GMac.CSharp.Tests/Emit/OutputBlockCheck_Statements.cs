using GMac.CSharp.Emit;
using GMac.Dsl.Tests.Support;

namespace GMac.CSharp.Tests.Emit;

/// <summary>
/// The text of an <c>output { … }</c> block is pasted into a <c>#region GMac</c> body as C#
/// statements: a directive or text that would run past the region is refused where it is written
/// (by the host, which adds its check to the DSL's diagnostics).
/// </summary>
public sealed class OutputBlockCheck_Statements
{
    private static string Macro(string output) => $$"""
        define macro M as
            inputs: { u : e3d.Vector }
            outputs: { w : e3d.Vector }
            performs:
                w = u;
                output {{{output}}};
        end macro
        """;

    [Theory]
    [InlineData("\n        «»#endregion\n    ", "'#endregion'")]
    [InlineData("\n      «»#region Mine\n    ", "'#region'")]
    [InlineData("\n    «»#pragma warning disable CS0168\n    ", "'#pragma'")]
    [InlineData("\n    «»#if DEBUG\n    x = 1;\n    #endif\n    ", "'#if'")]
    public void A_directive_is_refused_at_its_line(string output, string named)
    {
        var d = MarkedSource.AssertSingle(Macro(output), "GMAC0140", DslSnippets.E3d, OutputBlockCheck.Diagnostics);
        Assert.Contains(named, d.Message, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData(" «»/* unclosed comment ")]
    [InlineData(" var s = «»\"unclosed string; ")]
    [InlineData(" x = <u.e1> + 1«» ")]
    public void Text_that_is_not_whole_statements_is_refused(string output)
    {
        MarkedSource.AssertSingle(Macro(output), "GMAC0140", DslSnippets.E3d, OutputBlockCheck.Diagnostics);
    }

    [Theory]
    [InlineData(" // a comment with <w.e1> and { braces } ")]
    [InlineData("\n    Console.WriteLine(<u.e1> * 2);\n    if (<u.e2> > 0) { Log(\"#endregion is fine in a string\"); }\n")]
    public void Statements_and_comments_are_accepted(string output)
    {
        var project = SingleFileProject.Bind(DslSnippets.E3d + "\n" + Macro(output));
        Assert.DoesNotContain(OutputBlockCheck.Diagnostics(project), d => d.Code == "GMAC0140");
    }
}
