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

    /// <summary>Deepest an expression's tree may get through brackets and the operators that nest
    /// (prefix signs, products, quotients, powers): its stages recurse that deep. A flat sum adds no
    /// depth: the binder evaluates a long one as a balanced tree.</summary>
    public const int MaxOperatorChain = 1000;

    /// <summary>Most tokens (not counting whitespace and comments) read from one file: parsing and
    /// binding take memory and time in proportion, about 300 bytes a token, so a file is refused as
    /// it grows past this rather than after exhausting memory.</summary>
    public const int MaxTokens = 1_000_000;

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

    /// <summary>The parse tree, until the binder has read it (<see cref="ReleaseRoot"/>).</summary>
    internal GMacDslParser.CompilationUnitContext? Root { get; private set; }

    /// <summary>Drops the parse tree, many times the size of the text, once it is bound.</summary>
    internal void ReleaseRoot() => Root = null;

    public static SyntaxTree Parse(string filePath, string text)
    {
        var bag = new DiagnosticBag();
        var collector = new SyntaxErrorCollector(filePath, bag);
        var lexer = new GMacDslLexer(new AntlrInputStream(text));
        lexer.RemoveErrorListeners();
        lexer.AddErrorListener(collector);
        var source = new BudgetedTokenSource(lexer, MaxTokens);
        var tokens = new CommonTokenStream(source);
        tokens.Fill();
        if (source.Exceeded is { } last)
        {
            bag.ReportFileTooLarge(SpanOf(filePath, last), MaxTokens);
            return new SyntaxTree(filePath, text, null, bag.Items);
        }

        // An unclosed "/*" lexes as '/' and '*': say so at the "/*", and read the text before it,
        // without the errors its abrupt end causes there.
        var parserErrors = bag;
        var unterminated = FindUnterminatedComment(tokens.GetTokens());
        if (unterminated is not null)
        {
            bag.ReportSyntaxError(SpanOf(filePath, unterminated), "unterminated comment: '/*' has no closing '*/'");
            tokens = TokensBefore(tokens.GetTokens(), unterminated);
            parserErrors = new DiagnosticBag();
            collector = new SyntaxErrorCollector(filePath, parserErrors);
        }

        if (FindExcessiveNesting(tokens.GetTokens()) is { } deep)
        {
            if (deep.IsChain) bag.ReportOperatorChainTooLong(SpanOf(filePath, deep.Token), MaxOperatorChain);
            else bag.ReportNestingTooDeep(SpanOf(filePath, deep.Token), MaxNesting);
            return new SyntaxTree(filePath, text, null, bag.Items);
        }
        var root = ParseTokens(tokens, collector);
        if (unterminated is not null)
            bag.AddRange(parserErrors.Items.Where(d => d.Span.Start != unterminated.StartIndex || d.Span.Length != 0));
        return new SyntaxTree(filePath, text, root, bag.Items);
    }

    private static GMacDslParser.CompilationUnitContext ParseTokens(CommonTokenStream tokens, SyntaxErrorCollector collector)
    {
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
        return root;
    }

    /// <summary>
    /// The lexer's tokens on the default channel (whitespace and comments are dropped, not stored),
    /// at most <paramref name="budget"/> of them: then an end of file, and <see cref="Exceeded"/> is
    /// the first token over the budget.
    /// </summary>
    private sealed class BudgetedTokenSource(GMacDslLexer lexer, int budget) : ITokenSource
    {
        private int _count;

        public IToken? Exceeded { get; private set; }

        public IToken NextToken()
        {
            while (true)
            {
                var token = lexer.NextToken();
                if (token.Type == TokenConstants.EOF) return token;
                if (token.Channel != TokenConstants.DefaultChannel) continue;
                if (++_count <= budget) return token;
                Exceeded = token;
                return new CommonToken(TokenConstants.EOF) { Line = token.Line, Column = token.Column, StartIndex = token.StartIndex, StopIndex = token.StartIndex - 1 };
            }
        }

        public int Line => lexer.Line;
        public int Column => lexer.Column;
        public ICharStream InputStream => (ICharStream)lexer.InputStream;
        public string SourceName => lexer.SourceName;

        public ITokenFactory TokenFactory
        {
            get => lexer.TokenFactory;
            set => lexer.TokenFactory = value;
        }
    }

    /// <summary>A '/' directly followed by '*': a "/*" the lexer could not close with "*/".</summary>
    private static IToken? FindUnterminatedComment(IList<IToken> tokens)
    {
        for (var i = 0; i + 1 < tokens.Count; i++)
            if (tokens[i].Type == GMacDslLexer.SLASH && tokens[i + 1].Type == GMacDslLexer.STAR
                && tokens[i + 1].StartIndex == tokens[i].StopIndex + 1)
                return tokens[i];
        return null;
    }

    /// <summary>The tokens before <paramref name="end"/>, then an end of file where it starts.</summary>
    private static CommonTokenStream TokensBefore(IList<IToken> tokens, IToken end)
    {
        var kept = new List<IToken>(tokens.Take(end.TokenIndex));
        kept.Add(new CommonToken(TokenConstants.EOF)
        {
            Line = end.Line, Column = end.Column, StartIndex = end.StartIndex, StopIndex = end.StartIndex - 1,
        });
        var stream = new CommonTokenStream(new ListTokenSource(kept));
        stream.Fill();
        return stream;
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

    /// <summary>
    /// The first token at which brackets nest deeper than <see cref="MaxNesting"/>, or at which the
    /// expression's tree gets deeper than <see cref="MaxOperatorChain"/>: each bracket and each operator
    /// that nests (prefix signs, products, quotients, powers) adds a level until the end of its operand
    /// list; a binary + or - starts the next operand at the level of its bracket, since the binder
    /// balances sums.
    /// </summary>
    private static (IToken Token, bool IsChain)? FindExcessiveNesting(IList<IToken> tokens)
    {
        var depth = 0;
        var run = 0;       // the tree depth at this token
        var levelBase = 0; // the depth just inside the innermost open bracket
        var bases = new Stack<int>();
        var afterOperand = false;
        foreach (var token in tokens)
        {
            if (token.Channel != TokenConstants.DefaultChannel) continue;
            var isSumOperator = afterOperand && token.Type is GMacDslLexer.PLUS or GMacDslLexer.MINUS;
            afterOperand = token.Type is GMacDslLexer.ID or GMacDslLexer.INT or GMacDslLexer.FLOAT
                or GMacDslLexer.RPAREN or GMacDslLexer.RBRACKET or GMacDslLexer.RBRACE or GMacDslLexer.GT;
            switch (token.Type)
            {
                case GMacDslLexer.LPAREN or GMacDslLexer.LBRACKET or GMacDslLexer.LBRACE:
                    depth++;
                    bases.Push(levelBase);
                    levelBase = run = run + 1;
                    break;
                case GMacDslLexer.RPAREN or GMacDslLexer.RBRACKET or GMacDslLexer.RBRACE:
                    // The bracketed group is one operand at the depth before it opened.
                    depth = Math.Max(0, depth - 1);
                    run = Math.Max(0, levelBase - 1);
                    levelBase = bases.Count > 0 ? bases.Pop() : 0;
                    break;
                case GMacDslLexer.PLUS or GMacDslLexer.MINUS when isSumOperator:
                    run = levelBase;
                    break;
                case GMacDslLexer.MINUS or GMacDslLexer.PLUS or GMacDslLexer.STAR or GMacDslLexer.SLASH
                    or GMacDslLexer.CARET or GMacDslLexer.GP or GMacDslLexer.OP or GMacDslLexer.SP or GMacDslLexer.LCP
                    or GMacDslLexer.RCP or GMacDslLexer.FDP or GMacDslLexer.HIP or GMacDslLexer.CP or GMacDslLexer.ACP
                    or GMacDslLexer.VEE:
                    run++;
                    break;
                case GMacDslLexer.ID or GMacDslLexer.INT or GMacDslLexer.FLOAT or GMacDslLexer.DOT or GMacDslLexer.LT or GMacDslLexer.GT:
                    break;
                default:
                    run = levelBase; // a separator or keyword ends the operand
                    break;
            }
            if (depth > MaxNesting) return (token, false);
            if (run > MaxOperatorChain) return (token, true);
        }
        return null;
    }
}
