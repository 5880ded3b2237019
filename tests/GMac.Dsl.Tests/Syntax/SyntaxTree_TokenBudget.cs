using System.Text;
using GMac.Dsl.Syntax;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Syntax;

/// <summary>
/// Parsing and binding take memory in proportion to a file's tokens: a file is refused as its
/// tokens pass the budget, at the first token over it, before it is parsed at all.
/// </summary>
public sealed class SyntaxTree_TokenBudget
{
    [Fact]
    public void A_file_over_the_token_budget_is_refused_at_the_first_token_over_it()
    {
        // Four tokens on every line (whitespace is not a token), so token k is on line (k + 3) / 4.
        var text = new StringBuilder("define macro M as\ninputs: { u\n: e3d . Vector\n} outputs: {\nw : e3d .\nVector } performs:\n");
        var lines = SyntaxTree.MaxTokens / 4 + 1;
        for (var i = 6; i < lines; i++) text.Append("w = u;\n");
        text.Append("end macro\n");

        var project = SingleFileProject.Bind(text.ToString());

        var d = Assert.Single(project.Diagnostics);
        Assert.Equal("GMAC0004", d.Code);
        Assert.Equal((SyntaxTree.MaxTokens / 4 + 1, 1), (d.Span.Line, d.Span.Column));
        Assert.Contains($"more than {SyntaxTree.MaxTokens} tokens", d.Message);
        Assert.Empty(project.Model.Macros);
    }
}
