using System.Globalization;
using System.Text;
using GMac.Core.CodeGeneration;
using GMac.Dsl.Semantics;

namespace GMac.CSharp.Docs;

/// <summary>Prints the cookbook as Markdown (line ending "\n"), the text of docs/cookbook.md.</summary>
internal static class CookbookMarkdown
{
    /// <summary>The command that writes the file, quoted in it and in the test that keeps it current.</summary>
    public const string Command = "dotnet run --project src/GMac.Cli -- cookbook --dsl dsl -o docs/cookbook.md";

    public static string Write(IReadOnlyList<CookbookGroup> groups, string dslName)
    {
        var sb = new StringBuilder();
        var count = groups.Sum(g => g.Entries.Count);
        sb.Append("# Cookbook\n\n");
        sb.Append(Invariant($"The {Count(count, "macro")} of the GMacDSL library (`{dslName}/`), grouped by use. For each: what it computes, its inputs and outputs, "));
        sb.Append("the binding point you write in a C# file to use it (through the library's class bindings where one fits), and the operations of the code ");
        sb.Append("`gmac generate` writes for that binding point: additions (a subtraction counts as one), multiplications, divisions and function calls ");
        sb.Append("(`Math.Sqrt`, `Math.Sin`, …), counted as `gmac show --stats` counts them. Where a hand-written formula does the same job, it is given ");
        sb.Append("for comparison.\n\n");
        sb.Append("An object bound through a class binding (`//GMac.Bind(\"u\", \"Vector3D\", u);`) is read or written through the members the binding names ");
        sb.Append("(`u.x`, `u.y`, `u.z`); see `dsl/bindings.gmac`. A parameter without a fitting class binding is bound coefficient by coefficient: ");
        sb.Append("inputs from C# values (`u_e1`), outputs into assignable C# targets (`\"<w_e1>\"`). Rename them to your own.\n\n");
        sb.Append("This file is written by a command; do not edit it by hand. After changing a macro of the library, run\n\n");
        sb.Append("```sh\n").Append(Command).Append("\n```\n\n");
        sb.Append("A test fails while this file differs from what the command writes.\n\n");
        sb.Append("| group | macros |\n| --- | ---: |\n");
        foreach (var g in groups) sb.Append(Invariant($"| [{g.Title}](#{Anchor(g.Title)}) | {g.Entries.Count} |\n"));
        sb.Append('\n');
        foreach (var g in groups)
        {
            sb.Append("## ").Append(g.Title).Append("\n\n");
            if (g.Intro.Length > 0) sb.Append(g.Intro).Append("\n\n");
            sb.Append("From `").Append(RelativeName(g.File, dslName)).Append("`.\n\n");
            sb.Append("| macro | additions | multiplications | divisions | functions | hand formula |\n| --- | ---: | ---: | ---: | ---: | --- |\n");
            foreach (var e in g.Entries)
            {
                var s = e.Statistics;
                sb.Append(Invariant($"| [{e.Macro.Name}](#{Anchor(e.Macro.Name)}) | {s.Additions} | {s.Multiplications} | {s.Divisions} | {s.Calls} | {Cell(e.Hand ?? "")} |\n"));
            }
            sb.Append('\n');
            foreach (var e in g.Entries) Entry(sb, e);
        }
        return sb.ToString();
    }

    private static void Entry(StringBuilder sb, CookbookEntry e)
    {
        sb.Append("### ").Append(e.Macro.Name).Append("\n\n");
        if (e.Description.Length > 0) sb.Append(e.Description).Append("\n\n");
        sb.Append("`").Append(Signature(e.Macro)).Append("`\n\n");
        sb.Append("```csharp\n").Append(e.BindingPoint).Append("```\n\n");
        sb.Append("Generated: ").Append(Counts(e.Statistics)).Append(".\n");
        if (e.Hand is { } hand) sb.Append("By hand: ").Append(hand).Append('\n');
        sb.Append('\n');
    }

    public static string Signature(MacroSymbol macro)
    {
        static string List(IEnumerable<VariableSymbol> variables) => string.Join("; ", variables.Select(v => $"{v.Name} : {v.Class!.QualifiedName}"));
        return $"{macro.Name}: inputs {{ {List(macro.Inputs)} }} outputs {{ {List(macro.Outputs)} }}";
    }

    private static string Counts(CodeStatistics s) =>
        $"{Count(s.Additions, "addition")}, {Count(s.Multiplications, "multiplication")}, {Count(s.Divisions, "division")}, {Count(s.Calls, "function call")}";

    private static string Count(int n, string what) => Invariant($"{n} {what}{(n == 1 ? "" : "s")}");

    /// <summary>The anchor a forge gives a heading: lower case, spaces to hyphens, other punctuation dropped.</summary>
    private static string Anchor(string heading) =>
        string.Concat(heading.ToLowerInvariant().Select(c => c == ' ' ? "-" : char.IsLetterOrDigit(c) || c is '-' or '_' ? c.ToString() : ""));

    private static string Cell(string text) => text.Replace("|", "\\|", StringComparison.Ordinal);

    private static string RelativeName(string file, string dslName)
    {
        var full = "/" + file.Replace('\\', '/');
        var at = full.LastIndexOf("/" + dslName + "/", StringComparison.Ordinal);
        return at >= 0 ? full[(at + 1)..] : Path.GetFileName(file);
    }

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
