using System.Text.RegularExpressions;
using System.Xml.Linq;

namespace GMac.CSharp.Tests.Layering;

/// <summary>
/// The layering of the generator read from the repository's files: Core ← Dsl ← the C# host ← Cli,
/// Roslyn only in the host, and the <c>&lt;…&gt;</c> template syntax of binding text read only by the host.
/// Each rule gives its violations as sentences, so a test shows what broke.
/// </summary>
internal static partial class LayeringRules
{
    private const string Roslyn = "Microsoft.CodeAnalysis";

    /// <summary>The projects each src project may reference (by file name) and the packages it may use.</summary>
    private static readonly (string Project, string[] Projects, string[] Packages, string[] Requires)[] Allowed =
    [
        ("GMac.Core", [], [], []),
        ("GMac.Dsl", ["GMac.Core", "SafeFiles"], ["Antlr4.Runtime.Standard"], ["GMac.Core"]),
        ("GMac.CSharp", ["GMac.Dsl", "SafeFiles"], ["Microsoft.CodeAnalysis.CSharp"], ["GMac.Dsl", "Microsoft.CodeAnalysis.CSharp"]),
        // Core and Dsl come to the Cli through the host: its commands are thin, the host is their one way in.
        // StreamJsonRpc carries the language server (gmac lsp), a command like the others.
        ("GMac.Cli", ["GMac.CSharp"], ["System.CommandLine", "StreamJsonRpc"], ["GMac.CSharp"]),
    ];

    public static List<string> ProjectViolations(string root)
    {
        var problems = new List<string>();
        foreach (var (name, projects, packages, requires) in Allowed)
        {
            var path = Path.Combine(root, "src", name, name + ".csproj");
            if (!File.Exists(path))
            {
                problems.Add($"{name}: no project file at {path}");
                continue;
            }
            var xml = XDocument.Load(path);
            var referenced = xml.Descendants("ProjectReference").Select(r => Path.GetFileNameWithoutExtension((string?)r.Attribute("Include") ?? "")).ToList();
            var used = xml.Descendants("PackageReference").Select(r => (string?)r.Attribute("Include") ?? "").ToList();
            problems.AddRange(referenced.Where(r => !projects.Contains(r)).Select(r => $"{name} references project {r}"));
            problems.AddRange(used.Where(p => !packages.Contains(p)).Select(p => $"{name} uses package {p}"));
            problems.AddRange(requires.Where(r => !referenced.Contains(r) && !used.Contains(r)).Select(r => $"{name} does not reference {r}"));
        }
        return problems;
    }

    /// <summary>
    /// Sources under src/ and bench/ outside the host: none reads Roslyn, and none scans binding text
    /// for '&lt;' or calls the template helpers. The DSL grammar's generated parser names its own
    /// '&lt;' token and is left out; the DSL binder's <c>&lt;mv.blade&gt;</c> references of output
    /// blocks are GMacDSL syntax, read with a regular expression, not with '&lt;' scanning.
    /// </summary>
    public static List<string> SourceViolations(string root)
    {
        var problems = new List<string>();
        foreach (var folder in new[] { "src", "bench" })
        {
            var top = Path.Combine(root, folder);
            if (!Directory.Exists(top)) continue;
            foreach (var file in Directory.EnumerateFiles(top, "*.cs", SearchOption.AllDirectories))
            {
                var relative = Path.GetRelativePath(root, file).Replace('\\', '/');
                if (relative.StartsWith("src/GMac.CSharp/", StringComparison.Ordinal) || relative.Contains("/obj/", StringComparison.Ordinal)
                    || relative.Contains("/bin/", StringComparison.Ordinal) || relative.StartsWith("src/GMac.Dsl/Syntax/Generated/", StringComparison.Ordinal))
                    continue;
                var lines = File.ReadAllLines(file);
                for (var i = 0; i < lines.Length; i++)
                {
                    if (TemplateScanning().Match(lines[i]) is { Success: true } m)
                        problems.Add($"{relative}({i + 1}): {m.Value} reads template text outside the C# host layer");
                    if (!relative.StartsWith("bench/", StringComparison.Ordinal) && lines[i].Contains(Roslyn, StringComparison.Ordinal))
                        problems.Add($"{relative}({i + 1}): uses Roslyn outside the C# host layer");
                }
            }
        }
        return problems;
    }

    /// <summary>A '&lt;' character or one-character string, or a name of the template helpers the host replaced.</summary>
    [GeneratedRegex(@"'<'|""<""|\b(TemplateClose|TemplateParts|TemplateTarget|FindClosing|IsTemplate)\b")]
    private static partial Regex TemplateScanning();
}
