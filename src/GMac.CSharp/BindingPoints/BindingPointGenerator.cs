using System.Text;
using GMac.Core.CodeGeneration;
using GMac.CSharp.Emit;
using GMac.Dsl.Diagnostics;
using GMac.Dsl.Generation;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;
using Diagnostic = GMac.Dsl.Diagnostics.Diagnostic;
using DiagnosticDescriptor = GMac.Dsl.Diagnostics.DiagnosticDescriptor;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// Generates every binding point of a file and splices the statements in: the region and
/// <c>//GMac.</c> lines stay, the rest of the body is replaced, indented like the region, with
/// the file's own line ending. Any failure leaves the whole file's text as it was.
/// </summary>
internal static class BindingPointGenerator
{
    public static FileGeneration Generate(BindingPointFile file, GenerationContext context, bool includeStatistics)
    {
        var diagnostics = new List<Diagnostic>(file.Diagnostics);
        var regions = new List<GeneratedRegion>();
        // Temporaries avoid the names of every bind line, the names in the region's scope, and the
        // temporaries of regions already generated in the same member. All of these come from the
        // file's text in order, so a second run picks the same names.
        var temporariesByScope = new Dictionary<int, HashSet<string>>();
        var declaredBy = new List<(BindingPoint Point, IReadOnlySet<string> Names)>();
        foreach (var point in file.Points)
        {
            var earlier = temporariesByScope.TryGetValue(point.Scope.Id, out var t) ? t : temporariesByScope[point.Scope.Id] = new(StringComparer.Ordinal);
            bool IsTaken(string name) => file.Identifiers.Contains(name) || point.Scope.Names.Contains(name) || earlier.Contains(name);
            var region = GenerateRegion(file, point, context, includeStatistics, IsTaken, diagnostics);
            regions.Add(region);
            if (region.Code is null) continue;
            foreach (var token in SyntaxFactory.ParseTokens(region.Code).Where(t => t.IsKind(SyntaxKind.IdentifierToken)))
                earlier.Add(token.ValueText);
            var declared = DeclaredNames(region.Code);
            CheckDeclarations(file.Path, point, declared, declaredBy, diagnostics);
            declaredBy.Add((point, declared));
        }
        AddInvalidByteHints(file, diagnostics);
        diagnostics.Sort((a, b) => (a.Span.Line, a.Span.Column).CompareTo((b.Span.Line, b.Span.Column)));
        if (diagnostics.Count > 0) return new FileGeneration(file, file.Source.Text, regions, diagnostics);
        return new FileGeneration(file, Splice(file, regions), regions, diagnostics);
    }

    /// <summary>The locals a region's code declares: default outputs, temporaries, and any an output block declares.</summary>
    private static HashSet<string> DeclaredNames(string code)
    {
        var statements = CSharpSyntaxTree.ParseText(code, new CSharpParseOptions(LanguageVersion.Latest, kind: SourceCodeKind.Script)).GetRoot();
        return statements.DescendantNodes()
            .Select(n => n switch
            {
                VariableDeclaratorSyntax v => v.Identifier.ValueText,
                SingleVariableDesignationSyntax d => d.Identifier.ValueText,
                _ => null,
            })
            .OfType<string>()
            .ToHashSet(StringComparer.Ordinal);
    }

    /// <summary>
    /// A local the code declares that a parameter or local around the region, or an earlier region
    /// sharing its locals, already declares would not compile (CS0128, CS0136): report it at the
    /// <c>#region</c> rather than write the file. Temporaries avoid every such name; default output
    /// names (<c>w_e1</c>) and names an output block declares cannot move.
    /// </summary>
    private static void CheckDeclarations(string path, BindingPoint point, IReadOnlySet<string> declared,
        List<(BindingPoint Point, IReadOnlySet<string> Names)> declaredBy, List<Diagnostic> diagnostics)
    {
        var at = SourceSpan.At(path, point.RegionLineNumber, point.RegionColumn);
        const string fix = "bind the macro's outputs to variables of your own (//GMac.Bind(\"w\", …)) or rename the other one";
        foreach (var name in declared.Order(StringComparer.Ordinal))
        {
            if (point.Placement.Declared.TryGetValue(name, out var other))
            {
                diagnostics.Add(new(DiagnosticCodes.AlreadyDeclared, at, $"the code of '{point.MacroName}' declares '{name}', but {other} is already declared where it goes; {fix}"));
                continue;
            }
            var region = declaredBy.FirstOrDefault(r => r.Names.Contains(name) && r.Point.Placement.SharesLocalsWith(point.Placement));
            if (region.Point is not null)
                diagnostics.Add(new(DiagnosticCodes.AlreadyDeclared, at,
                    $"the code of '{point.MacroName}' declares '{name}', which the code of the region of line {region.Point.RegionLineNumber} ('{region.Point.MacroName}') declares too, in the same or an enclosing block; {fix}"));
        }
    }

    /// <summary>
    /// A file that is not valid UTF-8 keeps its bytes as they are, but the C# text read from a line
    /// holding such bytes may not be what the user's editor shows: a diagnostic on it says so.
    /// </summary>
    private static void AddInvalidByteHints(BindingPointFile file, List<Diagnostic> diagnostics)
    {
        if (!file.Source.HasInvalidBytes) return;
        for (var i = 0; i < diagnostics.Count; i++)
        {
            var d = diagnostics[i];
            if (!string.Equals(d.Span.FilePath, file.Path, StringComparison.Ordinal) || d.Span.Line < 1 || d.Span.Line > file.Lines.Count) continue;
            if (file.Source.FirstInvalidByte(file.Lines[d.Span.Line - 1]) is { } invalid)
                diagnostics[i] = d with { Message = $"{d.Message} (the file is not valid UTF-8: byte 0x{invalid.Byte:X2} at line {d.Span.Line}, column {invalid.Index + 1}; save the file as UTF-8)" };
        }
    }

    private static GeneratedRegion GenerateRegion(BindingPointFile file, BindingPoint point, GenerationContext context, bool includeStatistics,
        Func<string, bool> isTaken, List<Diagnostic> diagnostics)
    {
        if (ScalarTypeOf(file, point, context, diagnostics) is not { } scalarType) return new GeneratedRegion(point, null, null);
        if (FusedMultiplyAddOf(file, point, context, diagnostics) is not { } fma) return new GeneratedRegion(point, null, null);
        var batches = point.Specs.OfType<BatchSpec>().ToList();
        ReportSecondLines(file, batches, DiagnosticCodes.InvalidBatch, "Batch", "batch index", diagnostics);
        if (batches.Count > 1) return new GeneratedRegion(point, null, null);
        GenerationOutcome outcome;
        string? code;
        (DiagnosticDescriptor Descriptor, string Message)? problem;
        try
        {
            (outcome, code, problem) = MacroGeneration.GenerateCode(context, point.MacroName, point.Specs, point.RegionLineNumber, file.Path, generated => new CSharpEmitOptions
            {
                Indent = point.Indent,
                NewLine = point.NewLine,
                IncludeStatistics = includeStatistics,
                IsNameTaken = isTaken,
                ScalarType = scalarType,
                FusedMultiplyAdd = fma,
                DeclareOutputs = generated.Plan?.DefaultOutputs ?? false,
                MayOverwrite = BindingExpressions.Overwrites(generated.Result!.Block, point.Scope.Storage),
            }, batches.FirstOrDefault()?.Index);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // A defect of the generator must not take the other files down: report it here.
            diagnostics.Add(new(DiagnosticCodes.InternalError, SourceSpan.At(file.Path, point.RegionLineNumber, point.RegionColumn), $"internal error while generating '{point.MacroName}': {e.GetType().Name}: {e.Message}"));
            return new GeneratedRegion(point, null, null);
        }
        // Errors about the region as a whole come at its line, column 1: point at the #region itself.
        // One caused in the DSL is reported there, so the build shows the line to fix.
        foreach (var e in outcome.Errors)
        {
            if (e.Cause is { } cause) diagnostics.Add(new(e.Descriptor, cause, $"{e.Message} (binding point at {e.Span.FilePath}({e.Span.Line},{e.Span.Column}))"));
            else if (e.Span.Line == point.RegionLineNumber && e.Span.Column == 1) diagnostics.Add(e with { Span = e.Span with { Column = point.RegionColumn } });
            else diagnostics.Add(e);
        }
        if (problem is { } p)
        {
            // What makes a batch wrong is in its bindings: point at the Batch line that asks for the loop.
            var at = p.Descriptor == DiagnosticCodes.InvalidBatch && batches.Count > 0
                ? SourceSpan.At(file.Path, batches[0].Line, batches[0].Column)
                : SourceSpan.At(file.Path, point.RegionLineNumber, point.RegionColumn);
            diagnostics.Add(new(p.Descriptor, at, p.Message));
        }
        if (code is null) return new GeneratedRegion(point, outcome, null);
        if (VectorType.Find(scalarType) is { } vector && !file.ImportedNamespaces.Contains(vector.Namespace)) code = VectorTypeNames.Qualify(code, scalarType);
        return new GeneratedRegion(point, outcome, code) { ScalarType = scalarType, FusedMultiplyAdd = fma };
    }

    /// <summary>A binding point gives each of Type, Fma and Batch once: every later line of the kind is an error at that line.</summary>
    private static void ReportSecondLines<T>(BindingPointFile file, List<T> lines, DiagnosticDescriptor descriptor, string kind, string what,
        List<Diagnostic> diagnostics) where T : BindingSpec
    {
        foreach (var extra in lines.Skip(1))
            diagnostics.Add(new(descriptor, SourceSpan.At(file.Path, extra.Line, extra.Column),
                $"a second GMac.{kind} line; the binding point's {what} is already given at line {lines[0].Line}"));
    }

    /// <summary>
    /// The binding point's <c>//GMac.Type</c>, else the run's scalar type; null (with a diagnostic at
    /// the line) for a type gmac does not emit or a second Type line.
    /// </summary>
    private static string? ScalarTypeOf(BindingPointFile file, BindingPoint point, GenerationContext context, List<Diagnostic> diagnostics)
    {
        var lines = point.Specs.OfType<ScalarTypeSpec>().ToList();
        ReportSecondLines(file, lines, DiagnosticCodes.InvalidScalarType, "Type", "type", diagnostics);
        if (lines.Count == 0) return context.DefaultScalarType;
        var name = lines[0].TypeName;
        if (!CSharpEmitter.ScalarTypes.Contains(name))
        {
            var hint = name.ToLowerInvariant() switch
            {
                "float" or "single" or "system.single" or "f32" => "; did you mean 'float'?",
                "double" or "system.double" or "f64" => "; did you mean 'double'?",
                // C# names are case-sensitive: Vector256<Double> is not a type.
                _ when CSharpEmitter.ScalarTypeNamed(name.Replace(" ", "", StringComparison.Ordinal)) is { } type => $"; did you mean '{type}'?",
                _ => "",
            };
            diagnostics.Add(new(DiagnosticCodes.InvalidScalarType, SourceSpan.At(file.Path, lines[0].Line, lines[0].Column),
                $"GMac.Type(\"{name}\"): gmac writes code in {string.Join(" or ", CSharpEmitter.ScalarTypes)}, not '{name}'{hint}"));
            return null;
        }
        return lines.Count > 1 ? null : name;
    }

    /// <summary>
    /// The binding point's <c>//GMac.Fma</c>, else the run's choice (<c>--fma</c>); null (with a
    /// diagnostic at the line) for an argument other than true or false, or a second Fma line.
    /// </summary>
    private static bool? FusedMultiplyAddOf(BindingPointFile file, BindingPoint point, GenerationContext context, List<Diagnostic> diagnostics)
    {
        var lines = point.Specs.OfType<FusedMultiplyAddSpec>().ToList();
        ReportSecondLines(file, lines, DiagnosticCodes.InvalidFusedMultiplyAdd, "Fma", "choice", diagnostics);
        if (lines.Count == 0) return context.DefaultFusedMultiplyAdd;
        if (lines[0].Enabled is null)
        {
            diagnostics.Add(new(DiagnosticCodes.InvalidFusedMultiplyAdd, SourceSpan.At(file.Path, lines[0].Line, lines[0].Column),
                $"GMac.Fma({lines[0].Text}): the argument must be true or false (the C# literal, unquoted)"));
            return null;
        }
        return lines.Count > 1 ? null : lines[0].Enabled;
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
