using System.Text;
using GMac.Core.CodeGeneration;
using GMac.Dsl.BindingPoints;
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
        // Temporaries avoid the names of every bind line, the names in the region's scope, and the
        // temporaries of regions already generated in the same member. All of these come from the
        // file's text in order, so a second run picks the same names.
        var temporariesByScope = new Dictionary<int, HashSet<string>>();
        foreach (var point in file.Points)
        {
            var earlier = temporariesByScope.TryGetValue(point.Scope.Id, out var t) ? t : temporariesByScope[point.Scope.Id] = new(StringComparer.Ordinal);
            bool IsTaken(string name) => file.Identifiers.Contains(name) || point.Scope.Names.Contains(name) || earlier.Contains(name);
            var region = GenerateRegion(file, point, context, includeStatistics, IsTaken, diagnostics);
            regions.Add(region);
            if (region.Code is not null)
                foreach (var token in SyntaxFactory.ParseTokens(region.Code).Where(t => t.IsKind(SyntaxKind.IdentifierToken)))
                    earlier.Add(token.ValueText);
        }
        diagnostics.Sort((a, b) => a.Line != b.Line ? a.Line.CompareTo(b.Line) : a.Column.CompareTo(b.Column));
        if (diagnostics.Count > 0) return new FileGeneration(file, file.Source.Text, regions, diagnostics);
        return new FileGeneration(file, Splice(file, regions), regions, diagnostics);
    }

    private static GeneratedRegion GenerateRegion(BindingPointFile file, BindingPoint point, GenerationContext context, bool includeStatistics,
        Func<string, bool> isTaken, List<BindingDiagnostic> diagnostics)
    {
        GenerationOutcome outcome;
        try
        {
            outcome = BindingTextCheck.Generate(context, point.MacroName, point.Specs, point.RegionLineNumber);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // A defect of the generator must not take the other files down: report it here.
            diagnostics.Add(new(file.Path, point.RegionLineNumber, point.RegionColumn, "GMAC0409", $"internal error while generating '{point.MacroName}': {e.GetType().Name}: {e.Message}"));
            return new GeneratedRegion(point, null, null);
        }
        // Errors about the region as a whole come at its line, column 1: point at the #region itself.
        foreach (var e in outcome.Errors)
            diagnostics.Add(e.Source is { } at
                ? new(at.FilePath, at.Line, at.Column, e.Code, $"{e.Message} (binding point at {file.Path}({e.Line},{e.Column}))")
                : new(file.Path, e.Line, e.Line == point.RegionLineNumber && e.Column == 1 ? point.RegionColumn : e.Column, e.Code, e.Message));
        if (!outcome.Succeeded) return new GeneratedRegion(point, outcome, null);
        try
        {
            var code = CSharpEmitter.Emit(outcome.Result!.Block, new CSharpEmitOptions
            {
                Indent = point.Indent,
                NewLine = file.Source.NewLine,
                IncludeStatistics = includeStatistics,
                IsNameTaken = isTaken,
            });
            return new GeneratedRegion(point, outcome, code);
        }
        catch (InvalidOperationException e)
        {
            diagnostics.Add(new(file.Path, point.RegionLineNumber, point.RegionColumn, "GMAC0409", $"cannot print the code of macro '{point.MacroName}': {e.Message}"));
            return new GeneratedRegion(point, outcome, null);
        }
    }

    /// <summary>
    /// The file's text with each region's body replaced by its code (a region without code keeps
    /// its body); <paramref name="bodies"/>, when given, receives where each new body lies in it.
    /// </summary>
    internal static string Splice(BindingPointFile file, IReadOnlyList<GeneratedRegion> regions, List<(GeneratedRegion Region, int Start, int End)>? bodies = null)
    {
        var text = new StringBuilder(file.Source.Text.Length + 1024);
        var line = 0;
        foreach (var region in regions)
        {
            var point = region.Point;
            for (; line <= point.RegionLine; line++) text.Append(file.Lines[line]);
            for (; line < point.EndRegionLine; line++)
                if (region.Code is null || BindingLineReader.IsBindingLine(file.Lines[line]))
                    text.Append(file.Lines[line]);
            if (region.Code is null) continue;
            var start = text.Length;
            text.Append(region.Code);
            bodies?.Add((region, start, text.Length));
        }
        for (; line < file.Lines.Count; line++) text.Append(file.Lines[line]);
        return text.ToString();
    }
}
