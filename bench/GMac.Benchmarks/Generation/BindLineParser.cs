using System.Reflection;
using System.Text.RegularExpressions;
using GMac.Dsl.Generation;

namespace GMac.Benchmarks.Generation;

/// <summary>
/// Reads the binding points of the kernel sources embedded in this assembly, so that the report can
/// regenerate each one with the library and take its operation counts for exactly those bindings.
/// Only the forms the kernels use are understood: <c>Bind("p", "Class", "target")</c> and <c>Bind("p.blade", "value")</c>.
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
            if (current is null) continue;
            var bind = Bind().Match(line);
            if (!bind.Success) continue;
            var column = lines[i].IndexOf("//", StringComparison.Ordinal) + 1;
            var (first, second) = (bind.Groups[1].Value, bind.Groups[2].Value);
            if (bind.Groups[3].Success)
            {
                current.Add(new ClassBindingSpec(first, second, bind.Groups[3].Value, i + 1, column));
                continue;
            }
            var dot = first.IndexOf('.');
            if (dot < 0) throw new FormatException($"line {i + 1}: '{first}' names no blade (expected \"parameter.blade\").");
            current.Add(new CoefficientBindingSpec(first[..dot], first[(dot + 1)..], second, second.Contains('<'), i + 1, column));
        }
        return regions;
    }

    [GeneratedRegex(@"^#region\s+GMac\s*:\s*(\w+)")]
    private static partial Regex Region();

    [GeneratedRegex(@"^//GMac\.Bind\(\s*""([^""]*)""\s*,\s*""([^""]*)""\s*(?:,\s*""([^""]*)""\s*)?\)")]
    private static partial Regex Bind();
}
