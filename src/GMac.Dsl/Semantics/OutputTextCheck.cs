using System.Text.RegularExpressions;
using GMac.Dsl.Diagnostics;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace GMac.Dsl.Semantics;

/// <summary>
/// Checks the text of an <c>output { … }</c> block as what it becomes: C# statements pasted into a
/// <c>#region GMac</c> body. A directive there (<c>#endregion</c>, <c>#if</c>) would end the region
/// early or change what the rest of the file compiles, and an unclosed comment or string would
/// swallow the <c>#endregion</c>; the next run would then not find the region it wrote.
/// </summary>
internal static class OutputTextCheck
{
    // The text goes in a method body, as it goes in a region's; on a line of its own, as the emitter puts it.
    private const string Before = "class GMacOutputBlock { void Statements() {\n";
    private const string After = "\n} }";

    /// <summary>The first problem of <paramref name="text"/> (offset into it, message), or null when it is C# statements.</summary>
    /// <param name="placeholder">The <c>&lt;mv.blade&gt;</c> references, which become expressions.</param>
    public static (int Offset, string Message)? Problem(string text, Regex placeholder)
    {
        // A reference becomes an expression: a literal of the same length keeps every offset.
        var statements = placeholder.Replace(text, m => "0" + new string(' ', m.Length - 1));
        var tree = CSharpSyntaxTree.ParseText(Before + statements + After, new CSharpParseOptions(LanguageVersion.Latest));
        var root = tree.GetRoot();
        if (root.DescendantTrivia().FirstOrDefault(t => t.IsDirective) is { RawKind: not 0 } directive)
        {
            var name = (directive.GetStructure() as DirectiveTriviaSyntax)?.DirectiveNameToken.Text;
            return (Offset(directive.SpanStart),
                $"the output block holds the directive '#{name}': pasted into a '#region GMac' body it would end the region or change how the rest of the file compiles; write it outside the macro's region");
        }
        // An error inside the text first: one in the wrapper around it ("} expected") only follows from it.
        var error = tree.GetDiagnostics().Where(d => d.Severity == Microsoft.CodeAnalysis.DiagnosticSeverity.Error)
            .OrderBy(d => d.Location.SourceSpan.Start < Before.Length || d.Location.SourceSpan.Start > Before.Length + text.Length)
            .ThenBy(d => d.Location.SourceSpan.Start)
            .FirstOrDefault();
        if (error is null) return null;
        return (Offset(error.Location.SourceSpan.Start), $"the output block is not C# statements: {error.Id}: {error.GetMessage(System.Globalization.CultureInfo.InvariantCulture)}");

        int Offset(int position) => Math.Clamp(position - Before.Length, 0, text.Length);
    }

    /// <summary>Where <paramref name="offset"/> of a token's text lies, given the token's own position.</summary>
    public static SourceSpan SpanAt(SourceSpan token, string tokenText, int offset)
    {
        var before = tokenText.AsSpan(0, Math.Min(offset, tokenText.Length));
        var lineBreaks = before.Count('\n');
        var lastBreak = before.LastIndexOf('\n');
        var column = lastBreak < 0 ? token.Column + offset : offset - lastBreak;
        return new SourceSpan(token.FilePath, token.Line + lineBreaks, column, token.Start + offset, 1);
    }
}
