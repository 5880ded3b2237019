using System.Text.RegularExpressions;
using GMac.Dsl.Diagnostics;

namespace GMac.CSharp.Docs;

/// <summary>
/// What the comments of a <c>.gmac</c> file tell the cookbook. A file names its group on a line of
/// its own, <c>// cookbook group 3: Versors and motors</c> (the number orders the groups); the
/// comment lines right above a <c>define macro</c> describe it, and may hold
/// <c>// cookbook bind: u=Vector3D, w=Normal3D</c> (the class binding shown for a parameter),
/// <c>// cookbook hand: …</c> (the hand formula the generated code matches) and
/// <c>// cookbook group: Title</c> (another file's group for this macro). They stay comments, so
/// the DSL itself does not change.
/// </summary>
internal static partial class CookbookAnnotations
{
    /// <summary>
    /// The file's group line, if any, with the comment lines right after it (the group's introduction);
    /// an error for a second one or a malformed one.
    /// </summary>
    public static (int Order, string Title, string Intro, SourceSpan At)? FileGroup(string path, IReadOnlyList<string> lines, List<Diagnostic> problems)
    {
        (int, string, string, SourceSpan)? group = null;
        for (var i = 0; i < lines.Count; i++)
        {
            if (Annotation().Match(lines[i]) is not { Success: true } m || m.Groups["key"].Value != "group" || m.Groups["order"].Value.Length == 0) continue;
            var at = SourceSpan.At(path, i + 1, 1);
            if (group is { } first)
                problems.Add(new(Dsl.Diagnostics.DiagnosticCodes.CookbookAnnotation, at, $"a second 'cookbook group N:' line; the file's group is already given at line {first.Item4.Line}"));
            else if (!int.TryParse(m.Groups["order"].Value, out var order) || m.Groups["text"].Value.Length == 0)
                problems.Add(new(Dsl.Diagnostics.DiagnosticCodes.CookbookAnnotation, at, "expected '// cookbook group N: Title'"));
            else
            {
                var intro = lines.Skip(i + 1)
                    .TakeWhile(l => l.TrimStart().StartsWith("//", StringComparison.Ordinal) && !Mention().IsMatch(l))
                    .Select(l => l.TrimStart()[2..].Trim());
                group = (order, m.Groups["text"].Value, string.Join(" ", intro.Where(l => l.Length > 0)), at);
            }
        }
        return group;
    }

    /// <summary>
    /// The comment block right above the line <paramref name="line"/> (1-based) of a macro's
    /// declaration: its plain comment text, and its cookbook lines by key.
    /// </summary>
    public static MacroAnnotations ForMacro(string path, IReadOnlyList<string> lines, int line, List<Diagnostic> problems)
    {
        var start = line - 1;
        while (start > 0 && lines[start - 1].TrimStart().StartsWith("//", StringComparison.Ordinal)) start--;
        var description = new List<string>();
        string? hand = null, group = null;
        var bind = new List<(string Parameter, string Binding, SourceSpan At)>();
        for (var i = start; i < line - 1; i++)
        {
            var at = SourceSpan.At(path, i + 1, 1);
            if (Annotation().Match(lines[i]) is not { Success: true } m)
            {
                if (Mention().IsMatch(lines[i]))
                    problems.Add(new(Dsl.Diagnostics.DiagnosticCodes.CookbookAnnotation, at, "a cookbook line is '// cookbook KEY: text' with KEY one of group, bind, hand"));
                else description.Add(lines[i].TrimStart()[2..].Trim());
                continue;
            }
            var text = m.Groups["text"].Value;
            switch (m.Groups["key"].Value)
            {
                case "group" when m.Groups["order"].Value.Length > 0:
                    break; // the file's group line
                case "group":
                    group = text;
                    break;
                case "hand":
                    hand = text;
                    break;
                case "bind":
                    foreach (var item in text.Split(',', StringSplitOptions.TrimEntries | StringSplitOptions.RemoveEmptyEntries))
                    {
                        var eq = item.IndexOf('=');
                        if (eq <= 0 || eq == item.Length - 1)
                            problems.Add(new(Dsl.Diagnostics.DiagnosticCodes.CookbookAnnotation, at, $"cannot read '{item}': expected 'cookbook bind: PARAMETER=ClassBinding, …'"));
                        else bind.Add((item[..eq].Trim(), item[(eq + 1)..].Trim(), at));
                    }
                    break;
                default:
                    problems.Add(new(Dsl.Diagnostics.DiagnosticCodes.CookbookAnnotation, at, $"unknown cookbook key '{m.Groups["key"].Value}': expected group, bind or hand"));
                    break;
            }
        }
        return new MacroAnnotations(string.Join(" ", description.Where(d => d.Length > 0)), hand, group, bind);
    }

    [GeneratedRegex(@"^\s*//\s*cookbook (?<key>\w+)(?: (?<order>\d+))?:\s*(?<text>.*?)\s*$")]
    private static partial Regex Annotation();

    [GeneratedRegex(@"^\s*//\s*cookbook\b")]
    private static partial Regex Mention();
}
