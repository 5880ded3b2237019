using GMac.Core.Numerics;
using GMac.Dsl.Generation;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// Reads the C# text of a binding's value into the typed form the generator consumes: the one
/// place where the <c>&lt;…&gt;</c> template syntax is read. A quoted value is a template; a bare one
/// is a number or a C# expression. Each host expression is judged here for effects (evaluate once).
/// </summary>
internal static class BindingValueReader
{
    /// <summary>A value of a <c>//GMac.Bind</c> line: <paramref name="quoted"/> when it was a string literal.</summary>
    public static BindingValue Read(string text, bool quoted)
    {
        if (quoted) return Template(text);
        var trimmed = text.Trim();
        return Rational.TryParse(trimmed, out var number) ? new NumberValue(text, number) : Expression(text);
    }

    /// <summary>A <c>--bind NAME=VALUE</c> of <c>gmac show</c>: a template when it has a hole, else bare.</summary>
    public static BindingValue ReadCommandLine(string text) => Read(text, quoted: text.Contains('<'));

    /// <summary>A class binding on the C# object <paramref name="target"/>, judged for effects.</summary>
    public static ClassBindingSpec ClassBinding(string parameter, string classBinding, string target, int line, int column) =>
        new(parameter, classBinding, target, line, column) { TargetHasEffects = BindingExpressions.HasEffects(target.Trim()) };

    /// <summary>A bare C# expression, judged for effects on its trimmed text.</summary>
    public static HostExpression Expression(string text) => new(text, BindingExpressions.HasEffects(text.Trim()));

    /// <summary>
    /// Scalar text and holes of <paramref name="text"/> (trimmed); a hole's brackets nest (generic
    /// types, comparisons inside calls). An unclosed hole stops the reading with a problem.
    /// </summary>
    private static TemplateValue Template(string text)
    {
        var trimmed = text.Trim();
        var parts = new List<TemplatePart>();
        var scalar = new System.Text.StringBuilder();
        var i = 0;
        while (i < trimmed.Length)
        {
            if (trimmed[i] != '<')
            {
                scalar.Append(trimmed[i++]);
                continue;
            }
            var close = BindingExpressions.TemplateClose(trimmed, i);
            if (close < 0) return new TemplateValue(text, Flush(parts, scalar), Target: null, Problem: "unbalanced '<'");
            Flush(parts, scalar);
            var hole = trimmed[(i + 1)..close];
            parts.Add(new TemplateHole(new HostExpression(hole, BindingExpressions.HasEffects(hole))));
            i = close + 1;
        }
        return new TemplateValue(text, Flush(parts, scalar), OutputTarget(trimmed));
    }

    private static List<TemplatePart> Flush(List<TemplatePart> parts, System.Text.StringBuilder scalar)
    {
        if (scalar.Length > 0) parts.Add(new ScalarTextPart(scalar.ToString()));
        scalar.Clear();
        return parts;
    }

    /// <summary>"&lt;wx&gt;" → "wx": a template that is one hole and nothing else; a bracket inside makes it no target.</summary>
    private static string? OutputTarget(string trimmed) =>
        trimmed.Length > 2 && trimmed[0] == '<' && trimmed[^1] == '>' && trimmed.IndexOf('<', 1) < 0 ? trimmed[1..^1].Trim() : null;
}
