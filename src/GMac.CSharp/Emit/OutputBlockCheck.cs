using GMac.Dsl;
using GMac.Dsl.Diagnostics;
using GMac.Dsl.Semantics;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;
using Diagnostic = GMac.Dsl.Diagnostics.Diagnostic;

namespace GMac.CSharp.Emit;

/// <summary>
/// Checks the text of an <c>output { … }</c> block as what it becomes: C# statements pasted into a
/// <c>#region GMac</c> body. A directive there (<c>#endregion</c>, <c>#if</c>) would end the region
/// early or change what the rest of the file compiles, and an unclosed comment or string would
/// swallow the <c>#endregion</c>; the next run would then not find the region it wrote.
/// </summary>
internal static class OutputBlockCheck
{
    // The text goes in a method body, as it goes in a region's; on a line of its own, as the emitter puts it.
    private const string Before = "class GMacOutputBlock { void Statements() {\n";
    private const string After = "\n} }";

    /// <summary>
    /// The project's diagnostics with those of its output blocks as C#, in the project's order
    /// (file, line, column): what every command that loads a DSL for C# reports.
    /// </summary>
    public static IReadOnlyList<Diagnostic> Diagnostics(DslProject project)
    {
        var blocks = project.Model.Macros.Values
            .SelectMany(m => m.Statements.OfType<BoundOutputStatement>())
            .Select(o => Problem(o) is { } p ? new Diagnostic(DiagnosticCodes.InvalidOutputText, o.TextStart.Offset(o.Text, p.Offset), p.Message) : null)
            .OfType<Diagnostic>()
            .ToList();
        if (blocks.Count == 0) return project.Diagnostics;
        return project.Diagnostics.Concat(blocks)
            .OrderBy(d => d.Span.FilePath, StringComparer.Ordinal)
            .ThenBy(d => d.Span.Line).ThenBy(d => d.Span.Column)
            .ToList();
    }

    /// <summary>The first problem of the block's text (offset into it, message), or null when it is C# statements.</summary>
    public static (int Offset, string Message)? Problem(BoundOutputStatement output)
    {
        // A reference becomes an expression: a literal of the same length keeps every offset.
        var text = output.Text;
        var statements = string.Concat(output.Parts.Select(p => p is OutputReferencePart ? "0" + new string(' ', p.Text.Length - 1) : p.Text));
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
}
