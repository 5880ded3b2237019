using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// What the C# text of bindings means for the code pasted around it, decided on its syntax: which
/// storage an expression reads or writes (so an output that may overwrite an input still to be read
/// is held back), which storage two texts name alike (<c>p</c>, <c>this.p</c>, <c>(p)</c>,
/// <c>@p</c>), and which texts must be evaluated only once (calls, increments, assignments).
/// Types are unknown here, so different variables are taken as different storage unless the
/// declarations around say one may refer elsewhere (<see cref="StorageNames"/>).
/// </summary>
public static class BindingExpressions
{
    /// <summary>
    /// The '>' closing the '&lt;' at <paramref name="start"/> of a template, allowing nested brackets
    /// (generic types, comparisons inside calls); the '>' of a pointer member access <c>p->x</c> closes nothing.
    /// </summary>
    public static int TemplateClose(string text, int start)
    {
        var depth = 0;
        for (var i = start; i < text.Length; i++)
        {
            if (text[i] == '<') depth++;
            else if (text[i] == '>' && (i == 0 || text[i - 1] != '-') && --depth == 0) return i;
        }
        return -1;
    }

    /// <summary>
    /// Whether writing <paramref name="target"/> may change what <paramref name="input"/> reads. True
    /// unless both are understood and provably apart: different variables (that <paramref name="names"/>
    /// does not say may share storage), different members, or elements at different constant indices.
    /// </summary>
    public static bool MayAlias(string target, string input, StorageNames? names = null)
    {
        if (Path(Parse(target)) is not { } written) return true;
        if (ReadPaths(Parse(input)) is not { } read) return true;
        return read.Any(r => Overlap(written, r, names ?? StorageNames.None));
    }

    /// <summary>
    /// For <see cref="GMac.Core.CodeGeneration.CSharpEmitOptions.MayOverwrite"/>: whether writing an
    /// output of the block may change what one of its inputs reads, decided on their C# text.
    /// </summary>
    public static Func<string, string, bool> Overwrites(GMac.Core.CodeGeneration.CodeBlock block, StorageNames? names = null)
    {
        // Each text is parsed once per block, not once per pair.
        var written = new Dictionary<string, List<Step>?>(StringComparer.Ordinal);
        var read = new Dictionary<string, List<List<Step>>?>(StringComparer.Ordinal);
        return (output, input) =>
        {
            if (!block.OutputTargets.TryGetValue(output, out var target) || !block.InputText.TryGetValue(input, out var text)) return true;
            if (!written.TryGetValue(target, out var w)) written[target] = w = Path(Parse(target));
            if (!read.TryGetValue(text, out var r)) read[text] = r = ReadPaths(Parse(text));
            return w is null || r is null || r.Any(p => Overlap(w, p, names ?? StorageNames.None));
        };
    }

    /// <summary>Whether both texts name the same storage, spelt alike up to <c>this.</c>, parentheses, white space and escapes.</summary>
    public static bool SameStorage(string a, string b) =>
        Path(Parse(a)) is { } p && Path(Parse(b)) is { } q && p.Count == q.Count && p.Zip(q).All(s => s.First.Text == s.Second.Text);

    /// <summary>
    /// Whether the text does more than read storage: a call, an object creation, an assignment, an
    /// increment… Pasted at every use, it would run once per use; it must be evaluated once.
    /// </summary>
    public static bool HasEffects(string text) => !IsPureRead(Parse(text));

    private static ExpressionSyntax Parse(string text) => SyntaxFactory.ParseExpression(text.Trim());

    private static ExpressionSyntax Strip(ExpressionSyntax e)
    {
        while (e is ParenthesizedExpressionSyntax p) e = p.Expression;
        return e;
    }

    private static bool IsPureRead(ExpressionSyntax e)
    {
        if (e.ContainsDiagnostics) return false;
        e = Strip(e);
        return e switch
        {
            IdentifierNameSyntax or LiteralExpressionSyntax or ThisExpressionSyntax or BaseExpressionSyntax => true,
            MemberAccessExpressionSyntax m => m.Name is IdentifierNameSyntax && IsPureRead(m.Expression),
            ElementAccessExpressionSyntax el => IsPureRead(el.Expression) && el.ArgumentList.Arguments.All(a => a.RefKindKeyword.IsKind(SyntaxKind.None) && IsPureRead(a.Expression)),
            CastExpressionSyntax c => IsPureRead(c.Expression),
            PrefixUnaryExpressionSyntax u => u.Kind() is SyntaxKind.UnaryMinusExpression or SyntaxKind.UnaryPlusExpression
                or SyntaxKind.LogicalNotExpression or SyntaxKind.BitwiseNotExpression or SyntaxKind.PointerIndirectionExpression && IsPureRead(u.Operand),
            BinaryExpressionSyntax b => !b.IsKind(SyntaxKind.IsExpression) && !b.IsKind(SyntaxKind.AsExpression) && !b.IsKind(SyntaxKind.CoalesceExpression) && IsPureRead(b.Left) && IsPureRead(b.Right),
            ConditionalExpressionSyntax c => IsPureRead(c.Condition) && IsPureRead(c.WhenTrue) && IsPureRead(c.WhenFalse),
            _ => false,
        };
    }

    /// <summary>One step of a storage path: the root variable, a member, or an element (with its index text).</summary>
    private readonly record struct Step(string Text, bool IsElement, bool ConstantIndex);

    /// <summary>
    /// The storage an expression names as a path from a variable (<c>a</c>, <c>.b</c>, <c>[0]</c>), or
    /// null when it is not such a path (a call, a pointer member access, an operator…).
    /// </summary>
    private static List<Step>? Path(ExpressionSyntax e)
    {
        if (e.ContainsDiagnostics) return null;
        e = Strip(e);
        switch (e)
        {
            case IdentifierNameSyntax id:
                return [new Step(id.Identifier.ValueText, false, false)];
            case ThisExpressionSyntax or BaseExpressionSyntax:
                return [new Step("this", false, false)];
            case MemberAccessExpressionSyntax m when m.IsKind(SyntaxKind.SimpleMemberAccessExpression) && m.Name is IdentifierNameSyntax name:
            {
                // this.p and base.p are the field p.
                if (Strip(m.Expression) is ThisExpressionSyntax or BaseExpressionSyntax) return [new Step(name.Identifier.ValueText, false, false)];
                var path = Path(m.Expression);
                path?.Add(new Step("." + name.Identifier.ValueText, false, false));
                return path;
            }
            case ElementAccessExpressionSyntax el:
            {
                var path = Path(el.Expression);
                if (path is null) return null;
                var args = el.ArgumentList.Arguments;
                var text = "[" + string.Join(",", args.Select(a => Canonical(a.Expression))) + "]";
                path.Add(new Step(text, true, args.All(a => Strip(a.Expression) is LiteralExpressionSyntax l && l.IsKind(SyntaxKind.NumericLiteralExpression))));
                return path;
            }
            default:
                return null;
        }
    }

    /// <summary>Tokens with identifiers unescaped (<c>@p</c> and <c>\u0070</c> are <c>p</c>) and literals by value.</summary>
    private static string Canonical(ExpressionSyntax e) => string.Join(" ", Strip(e).DescendantTokens().Select(t =>
        t.IsKind(SyntaxKind.IdentifierToken) ? t.ValueText : t.IsKind(SyntaxKind.NumericLiteralToken) ? Convert.ToString(t.Value, System.Globalization.CultureInfo.InvariantCulture) : t.Text));

    /// <summary>Every storage path an expression reads, element indices included; null when it does anything else.</summary>
    private static List<List<Step>>? ReadPaths(ExpressionSyntax e)
    {
        if (e.ContainsDiagnostics) return null;
        e = Strip(e);
        var result = new List<List<Step>>();
        if (Path(e) is { } path)
        {
            result.Add(path);
            // a[i] also reads i.
            for (var x = e; x is ElementAccessExpressionSyntax or MemberAccessExpressionSyntax; x = Strip(x is ElementAccessExpressionSyntax el ? el.Expression : ((MemberAccessExpressionSyntax)x).Expression))
            {
                if (x is not ElementAccessExpressionSyntax access) continue;
                foreach (var a in access.ArgumentList.Arguments)
                {
                    if (ReadPaths(a.Expression) is not { } inner) return null;
                    result.AddRange(inner);
                }
            }
            return result;
        }
        IEnumerable<ExpressionSyntax>? parts = e switch
        {
            LiteralExpressionSyntax => [],
            CastExpressionSyntax c => [c.Expression],
            PrefixUnaryExpressionSyntax u when u.Kind() is SyntaxKind.UnaryMinusExpression or SyntaxKind.UnaryPlusExpression
                or SyntaxKind.LogicalNotExpression or SyntaxKind.BitwiseNotExpression => [u.Operand],
            BinaryExpressionSyntax b when !b.IsKind(SyntaxKind.IsExpression) && !b.IsKind(SyntaxKind.AsExpression) => [b.Left, b.Right],
            ConditionalExpressionSyntax c => [c.Condition, c.WhenTrue, c.WhenFalse],
            _ => null,
        };
        if (parts is null) return null;
        foreach (var part in parts)
        {
            if (ReadPaths(part) is not { } inner) return null;
            result.AddRange(inner);
        }
        return result;
    }

    /// <summary>Whether two storage paths may share storage: one contains the other unless a step tells them apart.</summary>
    private static bool Overlap(List<Step> a, List<Step> b, StorageNames names)
    {
        if (a[0].Text != b[0].Text) return names.MayShare(a[0].Text, b[0].Text);
        for (var i = 1; i < Math.Min(a.Count, b.Count); i++)
        {
            var (x, y) = (a[i], b[i]);
            if (x.Text == y.Text) continue;
            if (!x.IsElement && !y.IsElement) return false; // different fields
            if (x.IsElement && y.IsElement && x.ConstantIndex && y.ConstantIndex) return false; // a[0] and a[1]
            return true;
        }
        return true;
    }
}
