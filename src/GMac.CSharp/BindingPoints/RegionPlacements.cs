using System.Text;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// Tells where the statements of each region of a file would land. The file is parsed once more
/// with each region's body replaced by one probe statement (<c>__gmac_probe_3();</c>), so old
/// generated code does not matter: the probe must be a statement of a block, a switch section or
/// the top-level statements, and parse without errors around it. The same parse gives the locals
/// and parameters the region's code must not declare again.
/// </summary>
internal sealed class RegionPlacements
{
    private const string ProbeName = "__gmac_probe_";

    private readonly string _text;
    private readonly CSharpParseOptions[] _options;
    private readonly SyntaxTree?[] _trees;
    private readonly List<Diagnostic>?[] _errors;
    private readonly List<(int Position, int ProbeLine, int EndLine)> _probes = [];
    private readonly Dictionary<SyntaxNode, List<Declaration>> _declarations = [];

    /// <param name="lines">The file's lines with their terminators.</param>
    /// <param name="regions">Each region's <c>#region</c> and <c>#endregion</c> lines (0-based), in order and not nested.</param>
    /// <param name="options">Parse options to try in turn until the probe is in compiled code (plain, then Debug).</param>
    public RegionPlacements(IReadOnlyList<string> lines, IReadOnlyList<(int Line, int EndLine)> regions, string path, params CSharpParseOptions[] options)
    {
        var text = new StringBuilder();
        var line = 0;
        var probeLine = 0;
        for (var k = 0; k < regions.Count; k++)
        {
            var (regionLine, endLine) = regions[k];
            for (; line <= regionLine; line++, probeLine++) text.Append(lines[line]);
            var newLine = SourceText.LineEndingOf(lines[regionLine]);
            _probes.Add((text.Length, probeLine, endLine));
            text.Append(ProbeName).Append(k).Append("();").Append(newLine.Length > 0 ? newLine : "\n");
            probeLine++;
            line = endLine;
        }
        for (; line < lines.Count; line++) text.Append(lines[line]);
        _text = SourceText.ForParsing(text.ToString());
        Path = path;
        _options = options;
        _trees = new SyntaxTree?[options.Length];
        _errors = new List<Diagnostic>?[options.Length];
    }

    private string Path { get; }

    /// <summary>
    /// Where region <paramref name="k"/> is when statements cannot stand there, else null (with where
    /// to put it after <see cref="Fix"/>, if not in a method body between statements); and where its statements land.
    /// </summary>
    public (string? Problem, RegionPlacement Placement) Of(int k)
    {
        if (Probe(k) is not { } probe) return (null, RegionPlacement.Unknown);
        var (token, tree, errors) = probe;
        if (token.Parent is not IdentifierNameSyntax { Parent: InvocationExpressionSyntax { Parent: ExpressionStatementSyntax statement } }
            || statement.Parent is not (BlockSyntax or SwitchSectionSyntax or GlobalStatementSyntax { Parent: CompilationUnitSyntax }))
            return (Describe(token), RegionPlacement.Unknown);
        // The probe must also sit between whole statements: no error where it meets the code before and after it.
        var item = statement.Parent is GlobalStatementSyntax global ? (SyntaxNode)global : statement;
        var before = item.GetFirstToken().GetPreviousToken(includeZeroWidth: true);
        var after = item.GetLastToken().GetNextToken(includeZeroWidth: true);
        var from = before.RawKind == 0 ? 0 : before.SpanStart;
        var to = after.RawKind == 0 ? _text.Length : after.Span.End;
        var broken = errors.FirstOrDefault(d => d.Location.SourceSpan.End >= from && d.Location.SourceSpan.Start <= to);
        // A token the parser had to supply (the ';' of a declaration the region splits) counts as an error too.
        if (before.IsMissing || after.IsMissing) return ("inside a statement", RegionPlacement.Unknown);
        if (broken is not null)
            return (broken.Id == "CS8803" ? "after the file's type declarations, where top-level statements cannot come" : $"where statements break the code around them ({broken.Id}: {broken.GetMessage()})",
                RegionPlacement.Unknown);
        var block = statement.Parent switch
        {
            BlockSyntax b => b,
            SwitchSectionSyntax s => s.Parent!,
            _ => statement.Parent.Parent!,
        };
        var function = FunctionOf(statement);
        var declared = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (var d in DeclarationsIn(function))
            if (d.Scope.Span.Contains(token.SpanStart) || block.Span.Contains(d.Identifier.SpanStart))
                declared.TryAdd(d.Identifier.ValueText, $"{d.Kind} '{d.Identifier.ValueText}' of line {OriginalLine(tree.GetLineSpan(d.Identifier.Span).StartLinePosition.Line) + 1}");
        return (null, new RegionPlacement(function.SpanStart, block.SpanStart, block.Span.End, declared));
    }

    /// <summary>The probe of region <paramref name="k"/> in the first parse where it is compiled code; null when it is in none.</summary>
    private (SyntaxToken Token, SyntaxTree Tree, List<Diagnostic> Errors)? Probe(int k)
    {
        var position = _probes[k].Position;
        for (var i = 0; i < _options.Length; i++)
        {
            var tree = _trees[i] ??= CSharpSyntaxTree.ParseText(_text, _options[i], Path);
            var token = tree.GetRoot().FindToken(position);
            if (token.SpanStart == position && token.ValueText == ProbeName + k)
                return (token, tree, _errors[i] ??= tree.GetDiagnostics().Where(d => d.Severity == DiagnosticSeverity.Error).ToList());
        }
        return null;
    }

    /// <summary>The line of the file for a line of the probe text (lines after a probe move by the lines its region's body had).</summary>
    private int OriginalLine(int probeLine)
    {
        // The last probe above the line (probes are in order).
        int lo = 0, hi = _probes.Count - 1, last = -1;
        while (lo <= hi)
        {
            var mid = (lo + hi) / 2;
            if (_probes[mid].ProbeLine < probeLine) (last, lo) = (mid, mid + 1);
            else hi = mid - 1;
        }
        return last < 0 ? probeLine : _probes[last].EndLine + (probeLine - _probes[last].ProbeLine - 1);
    }

    /// <summary>Separates where a region is from where it should go, in <see cref="Of"/>'s problems.</summary>
    public const string Fix = "|";

    private static string Describe(SyntaxToken probe)
    {
        foreach (var node in probe.Parent!.Ancestors())
        {
            switch (node)
            {
                case AttributeListSyntax: return "in an attribute list";
                case BaseArgumentListSyntax: return "in an argument list";
                case SwitchExpressionArmSyntax or SwitchExpressionSyntax: return "in a switch expression";
                case InitializerExpressionSyntax: return "in an initializer";
                case ArrowExpressionClauseSyntax: return "in an expression body (=>)";
                case LambdaExpressionSyntax: return "in a lambda's expression body";
                case ExpressionStatementSyntax { Parent: LabeledStatementSyntax }: return "right after a label" + Fix + "after a statement";
                case ExpressionStatementSyntax { Parent: StatementSyntax or ElseClauseSyntax }: return "the single statement of an if, else or loop without braces" + Fix + "inside braces";
                case ExpressionStatementSyntax: return "where no statement can go";
                case BaseTypeDeclarationSyntax: return "among the members of a type";
                case BaseNamespaceDeclarationSyntax: return "in a namespace, outside any type";
                case StatementSyntax or MemberDeclarationSyntax: return "inside an expression";
            }
        }
        return "where no statement can go";
    }

    private static SyntaxNode FunctionOf(SyntaxNode node) => node.Ancestors().First(IsFunction);

    private static bool IsFunction(SyntaxNode node) =>
        node is AnonymousFunctionExpressionSyntax or LocalFunctionStatementSyntax or BaseMethodDeclarationSyntax or AccessorDeclarationSyntax
            or CompilationUnitSyntax;

    private sealed record Declaration(SyntaxToken Identifier, SyntaxNode Scope, string Kind);

    /// <summary>
    /// The parameters and locals of a function (not those of the lambdas and local functions in it,
    /// which may reuse outer names), each with the node its name is known in. For a name declared in
    /// an expression (<c>out var</c>, a pattern) that is the enclosing block: sometimes wider than C#'s, never narrower.
    /// </summary>
    private List<Declaration> DeclarationsIn(SyntaxNode function)
    {
        if (_declarations.TryGetValue(function, out var found)) return found;
        found = [];
        foreach (var p in ParametersOf(function)) found.Add(new(p.Identifier, function, "the parameter"));
        foreach (var node in function.DescendantNodes(n => n == function || !IsFunction(n)))
        {
            switch (node)
            {
                case VariableDeclaratorSyntax { Parent: VariableDeclarationSyntax { Parent: { } holder } } v when holder is not BaseFieldDeclarationSyntax:
                    found.Add(new(v.Identifier, holder is LocalDeclarationStatementSyntax ? BlockOf(holder, function) : holder, "the local"));
                    break;
                case ForEachStatementSyntax f:
                    found.Add(new(f.Identifier, f, "the loop variable"));
                    break;
                case CatchDeclarationSyntax c when c.Identifier.ValueText.Length > 0:
                    found.Add(new(c.Identifier, c.Parent!, "the exception variable"));
                    break;
                case SingleVariableDesignationSyntax s:
                    found.Add(new(s.Identifier, s.Ancestors().OfType<ForEachVariableStatementSyntax>().FirstOrDefault() as SyntaxNode ?? BlockOf(s, function), "the local"));
                    break;
                case LocalFunctionStatementSyntax l when l != function:
                    found.Add(new(l.Identifier, BlockOf(l, function), "the local function"));
                    break;
                case QueryClauseSyntax or FromClauseSyntax or QueryContinuationSyntax:
                    if (RangeVariable(node) is { } range) found.Add(new(range, node.Ancestors().OfType<QueryExpressionSyntax>().First(), "the range variable"));
                    break;
            }
        }
        return _declarations[function] = found;
    }

    private static IEnumerable<ParameterSyntax> ParametersOf(SyntaxNode function) => function switch
    {
        BaseMethodDeclarationSyntax m => m.ParameterList.Parameters,
        LocalFunctionStatementSyntax l => l.ParameterList.Parameters,
        ParenthesizedLambdaExpressionSyntax l => l.ParameterList.Parameters,
        SimpleLambdaExpressionSyntax l => [l.Parameter],
        AnonymousMethodExpressionSyntax a => a.ParameterList?.Parameters ?? default,
        AccessorDeclarationSyntax { Parent.Parent: IndexerDeclarationSyntax i } => i.ParameterList.Parameters,
        _ => [],
    };

    private static SyntaxToken? RangeVariable(SyntaxNode clause) => clause switch
    {
        FromClauseSyntax f => f.Identifier,
        LetClauseSyntax l => l.Identifier,
        JoinClauseSyntax j => j.Identifier,
        QueryContinuationSyntax c => c.Identifier,
        _ => null,
    };

    /// <summary>The block whose locals a declaration statement joins: a switch's sections share one.</summary>
    private static SyntaxNode BlockOf(SyntaxNode node, SyntaxNode function) =>
        node.Ancestors().TakeWhile(a => a != function).FirstOrDefault(a => a is BlockSyntax or SwitchStatementSyntax) ?? function;
}
