using System.Reflection;
using System.Text.RegularExpressions;
using GMac.Dsl.BindingPoints;
using GMac.Dsl.Generation;

namespace GMac.Benchmarks.Generation;

/// <summary>
/// Reads the binding points of the kernel sources embedded in this assembly, so that the report can
/// regenerate each one with the library and take its operation counts for exactly those bindings.
/// Each <c>//GMac.</c> line goes through <see cref="BindingLineReader"/>, as in gmac: a line gmac
/// rejects stops the report instead of being skipped.
/// </summary>
public static partial class BindLineParser
{
    /// <summary>The bindings of every <c>#region GMac : <paramref name="macroName"/></c> in the kernel's source, in order.</summary>
    public static IReadOnlyList<IReadOnlyList<BindingSpec>> RegionsOf(string kernelTypeName, string macroName)
    {
        var resource = $"Kernels/{kernelTypeName}.cs";
        using var stream = Assembly.GetExecutingAssembly().GetManifestResourceStream(resource)
            ?? throw new InvalidOperationException($"the source of {kernelTypeName} is not embedded as '{resource}'.");
        using var reader = new StreamReader(stream);
        return Parse(reader.ReadToEnd(), macroName);
    }

    /// <exception cref="FormatException">A binding line of a region of the macro is malformed.</exception>
    public static IReadOnlyList<IReadOnlyList<BindingSpec>> Parse(string source, string macroName)
    {
        var regions = new List<IReadOnlyList<BindingSpec>>();
        List<BindingSpec>? current = null;
        var lines = source.Split('\n');
        for (var i = 0; i < lines.Length; i++)
        {
            var line = lines[i].Trim();
            var region = Region().Match(line);
            if (region.Success)
            {
                current = region.Groups[1].Value == macroName ? [] : null;
                continue;
            }
            if (line.StartsWith("#endregion", StringComparison.Ordinal))
            {
                if (current is not null) regions.Add(current);
                current = null;
                continue;
            }
            if (current is null || BindingLineReader.Read(lines[i], i + 1) is not { } read) continue;
            current.Add(read.Spec ?? throw new FormatException($"line {read.Line}, column {read.Column}: {read.Error}"));
        }
        return regions;
    }

    [GeneratedRegex(@"^#region\s+GMac\s*:\s*(\w+)")]
    private static partial Regex Region();
}
