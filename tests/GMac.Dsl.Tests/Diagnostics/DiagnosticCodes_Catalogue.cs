using System.Reflection;
using System.Text.RegularExpressions;
using GMac.Dsl.Diagnostics;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Diagnostics;

/// <summary>The catalogue of codes is complete, well formed, and the same as the table users read.</summary>
public sealed class DiagnosticCodes_Catalogue
{
    /// <summary>The descriptors as declared, read independently of <see cref="DiagnosticCodes.All"/>.</summary>
    private static List<(string Name, DiagnosticDescriptor Descriptor)> Declared() => typeof(DiagnosticCodes)
        .GetFields(BindingFlags.Public | BindingFlags.Static)
        .Where(f => f.FieldType == typeof(DiagnosticDescriptor))
        .Select(f => (f.Name, (DiagnosticDescriptor)f.GetValue(null)!))
        .ToList();

    [Fact]
    public void Every_code_is_well_formed_defined_once_and_in_increasing_order()
    {
        var declared = Declared();
        Assert.True(declared.Count >= 50, $"only {declared.Count} descriptors found");
        Assert.Equal(declared.Select(d => d.Descriptor), DiagnosticCodes.All);
        foreach (var (name, d) in declared)
        {
            Assert.Matches(@"^GMAC0[0-4]\d\d$", d.Code);
            Assert.False(string.IsNullOrWhiteSpace(d.Meaning), $"{name} has no meaning");
            Assert.NotEqual(default, d.ReportedBy);
        }
        for (var i = 1; i < declared.Count; i++)
            Assert.True(string.CompareOrdinal(declared[i - 1].Descriptor.Code, declared[i].Descriptor.Code) < 0,
                $"{declared[i].Name} ({declared[i].Descriptor.Code}) does not come after {declared[i - 1].Name} ({declared[i - 1].Descriptor.Code})");
        Assert.Equal(declared.Count, declared.Select(d => d.Descriptor.Meaning).Distinct(StringComparer.Ordinal).Count());
    }

    [Fact]
    public void Dsl_warnings_are_the_only_warnings_before_the_binding_point_range()
    {
        foreach (var d in DiagnosticCodes.All.Where(d => string.CompareOrdinal(d.Code, "GMAC0300") < 0))
            Assert.Equal(d.Code.StartsWith("GMAC02", StringComparison.Ordinal) ? DiagnosticSeverity.Warning : DiagnosticSeverity.Error, d.Severity);
    }

    [Fact]
    public void Docs_table_lists_exactly_the_catalogue_with_meanings_and_commands()
    {
        var text = File.ReadAllText(Path.Combine(RepositoryPaths.Root, "docs", "diagnostics.md"));
        var rows = Regex.Matches(text, @"^\| (GMAC\d{4}) \| (error|warning) \| (.+?) \| (.+?) \|$", RegexOptions.Multiline)
            .Select(m => (Code: m.Groups[1].Value, Severity: m.Groups[2].Value, Meaning: m.Groups[3].Value, Where: m.Groups[4].Value))
            .ToList();
        var expected = DiagnosticCodes.All
            .Select(d => (d.Code, Severity: d.Severity == DiagnosticSeverity.Error ? "error" : "warning", d.Meaning, Where: Commands(d.ReportedBy)))
            .ToList();
        Assert.Equal(expected, rows);
    }

    [Fact]
    public void Readme_links_the_table()
    {
        var readme = File.ReadAllText(Path.Combine(RepositoryPaths.Root, "README.md"));
        Assert.Contains("(docs/diagnostics.md)", readme);
    }

    [Fact]
    public void A_diagnostic_prints_in_the_msbuild_format_with_the_severity_of_its_code()
    {
        var error = new Diagnostic(DiagnosticCodes.CyclicCall, SourceSpan.At("lib/a.gmac", 12, 5), "macro calls form a cycle: A -> B -> A");
        var warning = new Diagnostic(DiagnosticCodes.Unused, SourceSpan.At("lib/a.gmac", 3, 1), "transform 'T' is never used");

        Assert.Equal("lib/a.gmac(12,5): error GMAC0114: macro calls form a cycle: A -> B -> A", error.ToString());
        Assert.Equal("lib/a.gmac(3,1): warning GMAC0201: transform 'T' is never used", warning.ToString());
    }

    /// <summary>The "reported by" column: the commands in a fixed order, then the build step.</summary>
    private static string Commands(ReportedBy reportedBy)
    {
        (ReportedBy Flag, string Name)[] names =
        [
            (ReportedBy.Check, "check"), (ReportedBy.Generate, "generate"), (ReportedBy.Show, "show"),
            (ReportedBy.Verify, "verify"), (ReportedBy.Build, "MSBuild"), (ReportedBy.Cookbook, "cookbook"),
        ];
        return string.Join(", ", names.Where(n => reportedBy.HasFlag(n.Flag)).Select(n => n.Name));
    }
}
