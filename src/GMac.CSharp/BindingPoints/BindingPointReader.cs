using System.Text.RegularExpressions;
using GMac.Dsl.Diagnostics;
using GMac.Dsl.Generation;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;
using Diagnostic = GMac.Dsl.Diagnostics.Diagnostic;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// Finds the binding points of a C# file through Roslyn's region directives (so regions inside
/// strings or comments do not count) and reads their <c>//GMac.</c> lines with the shared <see cref="BindingLineReader"/>.
/// </summary>
internal static partial class BindingPointReader
{
    /// <summary>Cheap test that lets the tool skip parsing files that cannot hold a binding point.</summary>
    public static bool MayContainBindingPoints(string text) => text.Contains("GMac", StringComparison.Ordinal) && RegionMention().IsMatch(text);

    /// <summary>
    /// Positions of the directives a Debug build compiles. Configuration symbols are unknown here,
    /// so a region is skipped only when neither a plain nor a Debug build would compile it
    /// (<c>#if false</c>, <c>#if SOME_UNDEFINED_SYMBOL</c>), never because it is Debug-only.
    /// </summary>
    private static HashSet<int> DirectivesActiveInDebugBuilds(string text, string path)
    {
        var debug = CSharpSyntaxTree.ParseText(text, DebugBuild, path);
        return debug.GetRoot().DescendantTrivia()
            .Where(t => t.IsDirective && t.GetStructure() is DirectiveTriviaSyntax { IsActive: true })
            .Select(t => t.SpanStart)
            .ToHashSet();
    }

    private static readonly CSharpParseOptions DebugBuild = new(LanguageVersion.Latest, preprocessorSymbols: ["DEBUG", "TRACE"]);

    public static BindingPointFile Read(SourceText source)
    {
        var path = source.Path;
        // Roslyn gets the text with only CR, LF and CRLF as line breaks, so its line numbers are the editor's.
        var parsed = SourceText.ForParsing(source.Text);
        var tree = CSharpSyntaxTree.ParseText(parsed, path: path);
        var activeInSomeBuild = DirectivesActiveInDebugBuilds(parsed, path);
        var root = tree.GetRoot();
        var text = tree.GetText();
        var lines = SourceText.SplitLines(source.Text);
        var diagnostics = new List<Diagnostic>();
        var open = new Stack<(int Line, int Column, string? Macro, int Position)>();
        var found = new List<(string Macro, int Line, int Column, int EndLine, int Position)>();
        var otherDirectives = new List<(int Line, int Column, string Name)>();

        // Roslyn parses an unmatched #endregion as a bad directive, so classify directives by their text.
        foreach (var directive in root.DescendantTrivia().Where(t => t.IsDirective))
        {
            // A directive in a branch the compiler skips (#if false) is no directive: its region is not code.
            if (directive.GetStructure() is DirectiveTriviaSyntax { IsActive: false } && !activeInSomeBuild.Contains(directive.SpanStart)) continue;
            var position = tree.GetLineSpan(directive.Span).StartLinePosition;
            var line = position.Line;
            var column = position.Character + 1;
            var kind = DirectiveKind().Match(lines[line]);
            if (!kind.Success)
            {
                otherDirectives.Add((line, column, DirectiveName().Match(lines[line]).Groups[1].Value));
                continue;
            }
            if (kind.Groups[1].Value == "region")
            {
                var header = RegionHeader().Match(lines[line]);
                string? macro = null;
                if (header.Success)
                {
                    macro = header.Groups["name"].Value;
                    if (!Identifier().IsMatch(macro))
                    {
                        diagnostics.Add(new(DiagnosticCodes.InvalidMacroName, SourceSpan.At(path, line + 1, column), $"'#region GMac :' must be followed by a macro name, not '{macro}'"));
                        macro = "";
                    }
                }
                if (open.Any(o => o.Macro is not null))
                {
                    var outer = open.First(o => o.Macro is not null);
                    diagnostics.Add(new(DiagnosticCodes.NestedRegion, SourceSpan.At(path, line + 1, column),
                        $"region nested inside the GMac region of line {outer.Line + 1}: its body is generated, so it cannot hold other regions"));
                }
                open.Push((line, column, macro, directive.SpanStart));
                continue;
            }
            if (open.Count == 0)
            {
                diagnostics.Add(new(DiagnosticCodes.UnmatchedEndRegion, SourceSpan.At(path, line + 1, column), "#endregion without a matching #region"));
                continue;
            }
            var region = open.Pop();
            if (region.Macro is { Length: > 0 } name && !open.Any(o => o.Macro is not null))
                found.Add((name, region.Line, region.Column, line, region.Position));
        }
        foreach (var region in open)
            diagnostics.Add(new(DiagnosticCodes.UnmatchedRegion, SourceSpan.At(path, region.Line + 1, region.Column), "#region without a matching #endregion"));

        // A region's body is replaced: another directive in it (#pragma, #nullable, #if…) would be deleted,
        // changing how the rest of the file compiles.
        foreach (var r in found)
        foreach (var d in otherDirectives.Where(d => d.Line > r.Line && d.Line < r.EndLine))
            diagnostics.Add(new(DiagnosticCodes.DirectiveInRegion, SourceSpan.At(path, d.Line + 1, d.Column),
                $"#{d.Name} inside the GMac region of line {r.Line + 1}: the region's body is generated, so the directive would be deleted; move it before the #region or after the #endregion"));

        var placements = new RegionPlacements(lines, found.Select(r => (r.Line, r.EndLine)).ToList(), path, CSharpParseOptions.Default, DebugBuild);
        var bodies = found.Select(r => (Start: text.Lines[r.Line].End, End: text.Lines[r.EndLine].Start)).ToList();
        var scopes = new RegionScopes(root, bodies);
        var points = found.Select((r, k) =>
        {
            var (problem, placement) = placements.Of(k);
            if (problem?.Split(RegionPlacements.Fix) is [var where, .. var fix])
                diagnostics.Add(new(DiagnosticCodes.RegionNotAmongStatements, SourceSpan.At(path, r.Line + 1, r.Column),
                    $"the GMac region is {where}: its code is statements, which would not compile there; put the region {(fix is [var place] ? place : "in a method body, between statements")}"));
            return ReadPoint(path, lines, r.Macro, r.Line, r.Column, r.EndLine, scopes.Of(r.Position), diagnostics) with { Placement = placement };
        }).ToList();
        var bindNames = points.SelectMany(p => p.Bindings).SelectMany(b => BoundIdentifiers(b.Spec)).ToHashSet(StringComparer.Ordinal);
        diagnostics.Sort((a, b) => (a.Span.Line, a.Span.Column).CompareTo((b.Span.Line, b.Span.Column)));
        return new BindingPointFile(source, lines, points, diagnostics, bindNames, ImportedNamespaces(root));
    }

    /// <summary>
    /// The namespaces of the file's plain <c>using</c> directives (not aliases or <c>using static</c>),
    /// at any level: one inside a namespace block counts for the whole file, a rare overestimate.
    /// </summary>
    private static HashSet<string> ImportedNamespaces(SyntaxNode root) =>
        root.DescendantNodes(n => n is CompilationUnitSyntax or BaseNamespaceDeclarationSyntax)
            .OfType<UsingDirectiveSyntax>()
            .Where(u => u.Alias is null && u.StaticKeyword.IsKind(SyntaxKind.None) && u.NamespaceOrType is not null)
            .Select(u => u.NamespaceOrType.ToString().Replace(" ", "", StringComparison.Ordinal).Replace("global::", "", StringComparison.Ordinal))
            .ToHashSet(StringComparer.Ordinal);

    /// <summary>Every identifier in the C# text of a binding (templates included): names the generated code reads or writes.</summary>
    private static IEnumerable<string> BoundIdentifiers(BindingSpec spec)
    {
        var text = spec switch
        {
            CoefficientBindingSpec c => c.Value.Text,
            ClassBindingSpec c => c.Target,
            AssumptionSpec a => a.Expression,
            _ => "",
        };
        return SyntaxFactory.ParseTokens(text).Where(t => t.IsKind(SyntaxKind.IdentifierToken)).Select(t => t.ValueText);
    }

    private static BindingPoint ReadPoint(string path, IReadOnlyList<string> lines, string macro, int regionLine, int regionColumn, int endLine,
        RegionScope scope, List<Diagnostic> diagnostics)
    {
        var indent = LeadingWhiteSpace(lines[regionLine]);
        var bindings = new List<BindingLine>();
        for (var i = regionLine + 1; i < endLine; i++)
        {
            if (BindingLineReader.Read(lines[i], i + 1) is not { } read) continue;
            if (read.Spec is { } spec) bindings.Add(new BindingLine(spec));
            else diagnostics.Add(new(DiagnosticCodes.InvalidBindingLine, SourceSpan.At(path, read.Line, read.Column), read.Error!));
        }
        return new BindingPoint(macro, regionLine, endLine, indent, bindings, regionColumn, scope) { NewLine = SourceText.LineEndingOf(lines[regionLine]) };
    }

    private static string LeadingWhiteSpace(string line)
    {
        var i = 0;
        while (i < line.Length && line[i] is ' ' or '\t') i++;
        return line[..i];
    }

    [GeneratedRegex(@"^\s*#\s*region\s+GMac\s*:\s*(?<name>.*?)\s*$")]
    private static partial Regex RegionHeader();

    [GeneratedRegex(@"^\s*#\s*(region|endregion)\b")]
    private static partial Regex DirectiveKind();

    [GeneratedRegex(@"^\s*#\s*(\w*)")]
    private static partial Regex DirectiveName();

    [GeneratedRegex(@"#\s*region\s+GMac\b")]
    private static partial Regex RegionMention();

    [GeneratedRegex(@"^[A-Za-z_][A-Za-z0-9_]*$")]
    private static partial Regex Identifier();
}
