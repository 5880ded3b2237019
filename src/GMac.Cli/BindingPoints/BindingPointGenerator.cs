using System.Text;
using GMac.Core.CodeGeneration;
using GMac.Dsl.Generation;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;

namespace GMac.Cli.BindingPoints;

/// <summary>
/// Generates every binding point of a file and splices the statements in: the region and
/// <c>//GMac.</c> lines stay, the rest of the body is replaced, indented like the region, with
/// the file's own line ending. Any failure leaves the whole file's text as it was.
/// </summary>
internal static class BindingPointGenerator
{
    public static FileGeneration Generate(BindingPointFile file, GenerationContext context, bool includeStatistics)
    {
        var diagnostics = new List<BindingDiagnostic>(file.Diagnostics);
        var regions = new List<GeneratedRegion>();
        // Names taken by user code, plus the temporaries of regions already generated in this file
        // (two regions may share a method). Deterministic, so a second run picks the same names.
        var taken = new HashSet<string>(file.Identifiers, StringComparer.Ordinal);
        foreach (var point in file.Points)
        {
            var region = GenerateRegion(file, point, context, includeStatistics, taken, diagnostics);
            regions.Add(region);
            if (region.Code is not null)
                foreach (var token in SyntaxFactory.ParseTokens(region.Code).Where(t => t.IsKind(SyntaxKind.IdentifierToken)))
                    taken.Add(token.ValueText);
        }
        diagnostics.Sort((a, b) => a.Line != b.Line ? a.Line.CompareTo(b.Line) : a.Column.CompareTo(b.Column));
        if (diagnostics.Count > 0) return new FileGeneration(file, file.Source.Text, regions, diagnostics);
        return new FileGeneration(file, Splice(file, regions), regions, diagnostics);
    }

    private static GeneratedRegion GenerateRegion(BindingPointFile file, BindingPoint point, GenerationContext context, bool includeStatistics,
        HashSet<string> taken, List<BindingDiagnostic> diagnostics)
    {
        var before = diagnostics.Count;
        if (context.Project.Model.Macros.TryGetValue(point.MacroName, out var macro))
        {
            var outputs = macro.Outputs.Select(o => o.Name).ToHashSet(StringComparer.Ordinal);
            foreach (var binding in point.Bindings)
            {
                var parameter = binding.Spec switch
                {
                    CoefficientBindingSpec c => c.Parameter,
                    ClassBindingSpec c => c.Parameter,
                    _ => null,
                };
                if (parameter is not null && outputs.Contains(parameter) && !binding.TargetIsAssignable)
                    diagnostics.Add(new(file.Path, binding.Spec.Line, binding.Spec.Column, "GMAC0405",
                        $"output '{parameter}' is bound to '{binding.TargetText}', which cannot be assigned; use a variable, field, property or element, e.g. \"<w.x>\""));
            }
        }
        if (diagnostics.Count > before) return new GeneratedRegion(point, null, null);

        GenerationOutcome outcome;
        try
        {
            outcome = context.Generator.Generate(point.MacroName, point.Specs, point.RegionLineNumber);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // A defect of the generator must not take the other files down: report it here.
            diagnostics.Add(new(file.Path, point.RegionLineNumber, 1, "GMAC0409", $"internal error while generating '{point.MacroName}': {e.GetType().Name}: {e.Message}"));
            return new GeneratedRegion(point, null, null);
        }
        foreach (var e in outcome.Errors)
            diagnostics.Add(e.Source is { } at
                ? new(at.FilePath, at.Line, at.Column, e.Code, $"{e.Message} (binding point at {file.Path}({e.Line},{e.Column}))")
                : new(file.Path, e.Line, e.Column, e.Code, e.Message));
        if (!outcome.Succeeded) return new GeneratedRegion(point, outcome, null);
        try
        {
            var code = CSharpEmitter.Emit(outcome.Result!.Block, new CSharpEmitOptions
            {
                Indent = point.Indent,
                NewLine = file.Source.NewLine,
                IncludeStatistics = includeStatistics,
                IsNameTaken = taken.Contains,
            });
            return new GeneratedRegion(point, outcome, code);
        }
        catch (InvalidOperationException e)
        {
            diagnostics.Add(new(file.Path, point.RegionLineNumber, 1, "GMAC0409", $"cannot print the code of macro '{point.MacroName}': {e.Message}"));
            return new GeneratedRegion(point, outcome, null);
        }
    }

    private static string Splice(BindingPointFile file, IReadOnlyList<GeneratedRegion> regions)
    {
        var text = new StringBuilder(file.Source.Text.Length + 1024);
        var line = 0;
        foreach (var region in regions)
        {
            var point = region.Point;
            for (; line <= point.RegionLine; line++) text.Append(file.Lines[line]);
            for (; line < point.EndRegionLine; line++)
                if (file.Lines[line].TrimStart().StartsWith(BindingPointReader.LinePrefix, StringComparison.Ordinal))
                    text.Append(file.Lines[line]);
            text.Append(region.Code);
        }
        for (; line < file.Lines.Count; line++) text.Append(file.Lines[line]);
        return text.ToString();
    }
}
