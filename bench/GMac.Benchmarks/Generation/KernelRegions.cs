using System.Reflection;
using GMac.CSharp.BindingPoints;
using GMac.Dsl.Generation;

namespace GMac.Benchmarks.Generation;

/// <summary>
/// The binding points of the kernel sources embedded in this assembly, so that the report can
/// regenerate each one with the library and take its operation counts for exactly those bindings.
/// They are read by gmac's own reader (<see cref="BindingPointReader"/>): a file gmac rejects stops
/// the report instead of being skipped.
/// </summary>
public static class KernelRegions
{
    /// <summary>The bindings of every <c>#region GMac : <paramref name="macroName"/></c> in the kernel's source, in order.</summary>
    public static IReadOnlyList<IReadOnlyList<BindingSpec>> RegionsOf(string kernelTypeName, string macroName)
    {
        var resource = $"Kernels/{kernelTypeName}.cs";
        using var stream = Assembly.GetExecutingAssembly().GetManifestResourceStream(resource)
            ?? throw new InvalidOperationException($"the source of {kernelTypeName} is not embedded as '{resource}'.");
        using var reader = new StreamReader(stream);
        return Read(resource, reader.ReadToEnd(), macroName);
    }

    /// <exception cref="FormatException">gmac reports a problem in the source (a malformed binding line, a misplaced region).</exception>
    public static IReadOnlyList<IReadOnlyList<BindingSpec>> Read(string path, string source, string macroName)
    {
        var file = BindingPointReader.Read(SourceText.FromString(path, source));
        if (file.Diagnostics.FirstOrDefault() is { } problem)
            throw new FormatException($"line {problem.Span.Line}, column {problem.Span.Column}: {problem.Message}");
        return file.Points.Where(p => p.MacroName == macroName).Select(p => p.Specs).ToList();
    }
}
