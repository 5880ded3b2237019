using Antlr4.Runtime;
using Antlr4.Runtime.Misc;
using GMac.Dsl.Diagnostics;
using GMac.Dsl.Syntax.Generated;

namespace GMac.Dsl.Syntax;

/// <summary>
/// Turns ANTLR lexer and parser errors into diagnostics instead of console
/// output, with short messages that name the offending token.
/// </summary>
internal sealed class SyntaxErrorCollector(string filePath, DiagnosticBag diagnostics)
    : IAntlrErrorListener<IToken>, IAntlrErrorListener<int>
{
    private const int MaxExpectedShown = 8;

    public void SyntaxError(TextWriter output, IRecognizer recognizer, IToken offendingSymbol, int line,
        int charPositionInLine, string msg, RecognitionException e)
    {
        if (UnknownOperatorWord(recognizer, offendingSymbol) is { } word)
        {
            diagnostics.ReportSyntaxError(new SourceSpan(filePath, word.Line, word.Column + 1, word.StartIndex, word.StopIndex - word.StartIndex + 1),
                $"unknown operator '{Shorten(word.Text)}'; the products are {Products}");
            return;
        }
        var start = offendingSymbol?.StartIndex ?? 0;
        var length = offendingSymbol is null || offendingSymbol.Type == TokenConstants.EOF
            ? 0
            : Math.Max(0, offendingSymbol.StopIndex - offendingSymbol.StartIndex + 1);
        var span = new SourceSpan(filePath, Math.Max(1, line), charPositionInLine + 1, Math.Max(0, start), length);
        diagnostics.ReportSyntaxError(span, Describe(recognizer, offendingSymbol, msg));
    }

    public void SyntaxError(TextWriter output, IRecognizer recognizer, int offendingSymbol, int line,
        int charPositionInLine, string msg, RecognitionException e) =>
        diagnostics.ReportSyntaxError(new SourceSpan(filePath, Math.Max(1, line), charPositionInLine + 1, 0, 1), msg);

    private const string Products = "gp, op, sp, lcp, rcp, fdp, hip, cp, acp, vee (and +, -, *, /, ^)";

    /// <summary>
    /// In `y = a meet b` the parser ends the statement after `a` and reads `meet b` as a new one
    /// missing its '='. A name between the end of an operand and the offending token, all on one
    /// line, is an operator word the language does not have.
    /// </summary>
    private static IToken? UnknownOperatorWord(IRecognizer recognizer, IToken? token)
    {
        if (token is null || recognizer is not Parser { InputStream: ITokenStream stream }) return null;
        IToken? Previous(int index)
        {
            for (var i = index - 1; i >= 0; i--)
                if (stream.Get(i) is { Channel: TokenConstants.DefaultChannel } t) return t;
            return null;
        }
        if (Previous(token.TokenIndex) is not { Type: GMacDslLexer.ID } word || word.Line != token.Line) return null;
        if (Previous(word.TokenIndex) is not { } operand || operand.Line != word.Line) return null;
        var endsOperand = operand.Type is GMacDslLexer.ID or GMacDslLexer.INT or GMacDslLexer.FLOAT || operand.Text is ")" or "]" or ">";
        var startsOperand = token.Type is GMacDslLexer.ID or GMacDslLexer.INT or GMacDslLexer.FLOAT || token.Text is "(" or "-";
        return endsOperand && startsOperand ? word : null;
    }

    private static string Describe(IRecognizer recognizer, IToken? token, string fallback)
    {
        if (token is null || recognizer is not Parser parser) return fallback;
        var found = token.Type == TokenConstants.EOF ? "end of file" : $"'{Shorten(token.Text)}'";
        if (fallback.StartsWith("missing ", StringComparison.Ordinal)) return fallback.Replace(" at ", " before ", StringComparison.Ordinal);
        IntervalSet expected;
        try
        {
            expected = parser.GetExpectedTokens();
        }
        catch (ArgumentException)
        {
            return $"unexpected {found}";
        }
        var names = expected.ToList()
            .Where(t => t > 0)
            .Select(t => parser.Vocabulary.GetDisplayName(t))
            .ToList();
        if (names.Count == 0 || names.Count > MaxExpectedShown) return $"unexpected {found}";
        return $"unexpected {found}; expected {string.Join(", ", names)}";
    }

    private static string Shorten(string text)
    {
        text = text.Replace("\r", "\\r", StringComparison.Ordinal).Replace("\n", "\\n", StringComparison.Ordinal);
        return text.Length <= 30 ? text : text[..27] + "...";
    }
}
