using Antlr4.Runtime;
using Antlr4.Runtime.Atn;
using Antlr4.Runtime.Misc;
using GMac.Dsl.Diagnostics;
using GMac.Dsl.Syntax.Generated;

namespace GMac.Dsl.Syntax;

/// <summary>
/// One parsed <c>.gmac</c> file. Parsing never throws: errors are recovered from
/// and reported, so a single run lists every syntax error of the file.
/// </summary>
public sealed class SyntaxTree
{
    /// <summary>Deeper bracket or prefix-operator nesting is refused before parsing, so
    /// that a recursive-descent parser cannot exhaust the stack.</summary>
    public const int MaxNesting = 200;

    /// <summary>Longest run of operators in one expression.</summary>
    public const int MaxOperatorChain = 2000;

    private SyntaxTree(string filePath, string text, GMacDslParser.CompilationUnitContext? root,
        IReadOnlyList<Diagnostic> diagnostics)
    {
        FilePath = filePath;
        Text = text;
        Root = root;
        Diagnostics = diagnostics;
    }

    public string FilePath { get; }
    public string Text { get; }
    public IReadOnlyList<Diagnostic> Diagnostics { get; }

    internal GMacDslParser.CompilationUnitContext? Root { get; }

    public static SyntaxTree Parse(string filePath, string text)
    {
        var bag = new DiagnosticBag();
        var collector = new SyntaxErrorCollector(filePath, bag);
        var lexer = new GMacDslLexer(new AntlrInputStream(text));
        lexer.RemoveErrorListeners();
        lexer.AddErrorListener(collector);
        var tokens = new CommonTokenStream(lexer);
        tokens.Fill();

        if (FindExcessiveNesting(tokens.GetTokens()) is { } deep)
        {
            bag.ReportNestingTooDeep(SpanOf(filePath, deep), MaxNesting);
            return new SyntaxTree(filePath, text, null, bag.Items);
        }

        // Two-stage parse: the fast SLL prediction almost always suffices; only when it
        // fails is the file parsed again with full LL prediction and error recovery.
        var parser = new GMacDslParser(tokens);
        parser.RemoveErrorListeners();
        parser.Interpreter.PredictionMode = PredictionMode.SLL;
        parser.ErrorHandler = new BailErrorStrategy();
        GMacDslParser.CompilationUnitContext root;
        try
        {
            root = parser.compilationUnit();
        }
        catch (ParseCanceledException)
        {
            tokens.Seek(0);
            parser.Reset();
            parser.AddErrorListener(collector);
            parser.ErrorHandler = new DefaultErrorStrategy();
            parser.Interpreter.PredictionMode = PredictionMode.LL;
            root = parser.compilationUnit();
        }
        return new SyntaxTree(filePath, text, root, bag.Items);
    }

    internal static SourceSpan SpanOf(string filePath, IToken token) =>
        new(filePath, Math.Max(1, token.Line), token.Column + 1, Math.Max(0, token.StartIndex),
            token.Type == TokenConstants.EOF ? 0 : Math.Max(0, token.StopIndex - token.StartIndex + 1));

    internal static SourceSpan SpanOf(string filePath, ParserRuleContext context)
    {
        var start = context.Start;
        var stop = context.Stop ?? start;
        var length = stop.StopIndex >= start.StartIndex ? stop.StopIndex - start.StartIndex + 1 : 0;
        return new SourceSpan(filePath, Math.Max(1, start.Line), start.Column + 1, Math.Max(0, start.StartIndex), length);
    }

    private static IToken? FindExcessiveNesting(IList<IToken> tokens)
    {
        var depth = 0;
        var operatorRun = 0;
        foreach (var token in tokens)
        {
            if (token.Channel != TokenConstants.DefaultChannel) continue;
            switch (token.Type)
            {
                case GMacDslLexer.LPAREN or GMacDslLexer.LBRACKET or GMacDslLexer.LBRACE:
                    depth++;
                    break;
                case GMacDslLexer.RPAREN or GMacDslLexer.RBRACKET or GMacDslLexer.RBRACE:
                    depth = Math.Max(0, depth - 1);
                    break;
            }
            // Operator chains build deep trees that later stages walk recursively.
            operatorRun = token.Type switch
            {
                GMacDslLexer.MINUS or GMacDslLexer.PLUS or GMacDslLexer.STAR or GMacDslLexer.SLASH
                    or GMacDslLexer.CARET or GMacDslLexer.LPAREN or GMacDslLexer.GP or GMacDslLexer.OP
                    or GMacDslLexer.SP or GMacDslLexer.LCP or GMacDslLexer.RCP or GMacDslLexer.FDP
                    or GMacDslLexer.HIP or GMacDslLexer.CP or GMacDslLexer.ACP => operatorRun + 1,
                GMacDslLexer.ID or GMacDslLexer.INT or GMacDslLexer.FLOAT or GMacDslLexer.DOT or GMacDslLexer.LT
                    or GMacDslLexer.GT or GMacDslLexer.RPAREN or GMacDslLexer.RBRACKET or GMacDslLexer.LBRACKET => operatorRun,
                _ => 0,
            };
            if (depth > MaxNesting || operatorRun > MaxOperatorChain) return token;
        }
        return null;
    }
}
