using GMac.CSharp.BindingPoints;
using GMac.Dsl.Diagnostics;
using GMac.Dsl.Semantics;
using Microsoft.CodeAnalysis.CSharp;
using static GMac.Dsl.Diagnostics.DiagnosticCodes;

namespace GMac.CSharp.Docs;

/// <summary>
/// The library's macros grouped by use, each with the binding point a user writes for it and the
/// operation counts of the code <c>gmac generate</c> writes for that binding point: the content
/// of docs/cookbook.md (<c>gmac cookbook</c>). Groups, descriptions, class bindings and hand
/// formulas come from comments of the library (<see cref="CookbookAnnotations"/>).
/// </summary>
internal static class Cookbook
{
    /// <summary>What the cookbook shows as the binding point's file, in messages about it.</summary>
    public const string PointPath = "docs/cookbook.md";

    /// <summary>The text of docs/cookbook.md, or null with the problems that stop it; <paramref name="dslName"/> names the library's folder in the text.</summary>
    public static (string? Markdown, IReadOnlyList<Diagnostic> Problems) Markdown(GenerationContext context, string dslName)
    {
        var (groups, problems) = Build(context);
        return (problems.Count == 0 ? CookbookMarkdown.Write(groups, dslName) : null, problems);
    }

    /// <summary>The groups in order, or the problems (GMAC0005) that stop the cookbook from being written.</summary>
    public static (IReadOnlyList<CookbookGroup> Groups, IReadOnlyList<Diagnostic> Problems) Build(GenerationContext context)
    {
        var problems = new List<Diagnostic>();
        var model = context.Project.Model;
        var files = context.Project.SyntaxTrees.ToDictionary(t => t.FilePath, t => SourceText.SplitLines(t.Text).Select(l => l.TrimEnd('\r', '\n')).ToList(), StringComparer.Ordinal);
        var fileGroups = new Dictionary<string, (int Order, string Title, string Intro, SourceSpan At)>(StringComparer.Ordinal);
        foreach (var (path, lines) in files)
            if (CookbookAnnotations.FileGroup(path, lines, problems) is { } group) fileGroups[path] = group;
        foreach (var same in fileGroups.GroupBy(g => g.Value.Order).Where(g => g.Count() > 1))
            foreach (var (_, group) in same.Skip(1))
                problems.Add(new(CookbookAnnotation, group.At, $"group number {same.Key} is already taken by '{same.First().Value.Title}' ({same.First().Value.At.FilePath})"));

        var pending = new List<(string GroupFile, MacroSymbol Macro, MacroAnnotations Annotations, string Point)>();
        foreach (var macro in model.Macros.Values.OrderBy(m => m.Declaration.FilePath, StringComparer.Ordinal).ThenBy(m => m.Declaration.Line))
        {
            var path = macro.Declaration.FilePath;
            var annotations = CookbookAnnotations.ForMacro(path, files[path], macro.Declaration.Line, problems);
            string groupFile;
            if (annotations.Group is { } title)
            {
                var named = fileGroups.FirstOrDefault(g => g.Value.Title == title);
                if (named.Key is null)
                {
                    problems.Add(new(CookbookAnnotation, macro.Declaration, $"macro '{macro.Name}' names cookbook group '{title}', which no file declares; groups: {string.Join(", ", fileGroups.Values.Select(g => $"'{g.Title}'"))}"));
                    continue;
                }
                groupFile = named.Key;
            }
            else if (fileGroups.ContainsKey(path)) groupFile = path;
            else
            {
                problems.Add(new(CookbookAnnotation, macro.Declaration, $"macro '{macro.Name}' has no cookbook group: give its file a line '// cookbook group N: Title'"));
                continue;
            }
            if (BindingPoint(macro, annotations, model, problems) is { } point) pending.Add((groupFile, macro, annotations, point));
        }
        // Generated on every core, as gmac generate does with its files (the context is safe for that), then kept in library order.
        var generated = new (Core.CodeGeneration.CodeStatistics? Statistics, List<Diagnostic> Problems)[pending.Count];
        Parallel.For(0, pending.Count, new ParallelOptions { MaxDegreeOfParallelism = Environment.ProcessorCount }, i =>
        {
            var found = new List<Diagnostic>();
            generated[i] = (Statistics(context, pending[i].Macro, pending[i].Point, found), found);
        });
        var entries = new List<(string GroupFile, CookbookEntry Entry)>();
        for (var i = 0; i < pending.Count; i++)
        {
            problems.AddRange(generated[i].Problems);
            var (groupFile, macro, annotations, point) = pending[i];
            if (generated[i].Statistics is { } statistics)
                entries.Add((groupFile, new CookbookEntry(macro, annotations.Description, point, statistics, annotations.Hand)));
        }
        var groups = fileGroups
            .OrderBy(g => g.Value.Order)
            .Select(g => new CookbookGroup(g.Value.Order, g.Value.Title, g.Value.Intro, g.Key, entries.Where(e => e.GroupFile == g.Key).Select(e => e.Entry).ToList()))
            .Where(g => g.Entries.Count > 0)
            .ToList();
        return (groups, problems);
    }

    /// <summary>
    /// The <c>#region GMac</c> block a user writes: each parameter through the class binding its
    /// annotation names, else through the library's binding named after its class (<c>Vector3D</c>
    /// for <c>e3d.Vector</c>) or the only one that binds exactly its coefficients, else coefficient
    /// by coefficient (inputs from C# locals, outputs into them).
    /// </summary>
    private static string? BindingPoint(MacroSymbol macro, MacroAnnotations annotations, SemanticModel model, List<Diagnostic> problems)
    {
        var failed = false;
        foreach (var (parameter, binding, at) in annotations.Bind)
        {
            var variable = macro.Inputs.Concat(macro.Outputs).FirstOrDefault(p => p.Name == parameter);
            if (variable is null)
                Fail(at, $"'cookbook bind: {parameter}={binding}': macro '{macro.Name}' has no input or output '{parameter}'");
            else if (!model.ClassBindings.TryGetValue(binding, out var symbol))
                Fail(at, $"'cookbook bind: {parameter}={binding}': no class binding '{binding}' is defined");
            else if (symbol.Frame != variable.Class!.Frame)
                Fail(at, $"'cookbook bind: {parameter}={binding}': '{binding}' binds frame '{symbol.Frame.Name}', '{parameter}' is of frame '{variable.Class.Frame.Name}'");
        }
        if (failed) return null;

        var lines = new List<string> { $"#region GMac : {macro.Name}" };
        foreach (var parameter in macro.Inputs.Concat(macro.Outputs))
        {
            var binding = annotations.Bind.FirstOrDefault(b => b.Parameter == parameter.Name).Binding ?? ClassBindingOf(parameter.Class!, model);
            if (binding is not null)
            {
                lines.Add($"//GMac.Bind(\"{parameter.Name}\", \"{binding}\", {Identifier(parameter.Name)});");
                continue;
            }
            var @class = parameter.Class!;
            foreach (var blade in @class.VariableBlades.Order())
            {
                var name = blade != 0 ? $"{parameter.Name}_{@class.Frame.BladeName(blade).Replace('^', '_')}"
                    : @class.VariableBlades.Count == 1 ? parameter.Name : $"{parameter.Name}_s";
                var value = parameter.Kind == VariableKind.Input ? Identifier(name) : $"\"<{name}>\"";
                lines.Add($"//GMac.Bind(\"{parameter.Name}.{@class.Frame.BladeName(blade)}\", {value});");
            }
        }
        lines.Add("#endregion");
        return string.Join("\n", lines) + "\n";

        void Fail(SourceSpan at, string message)
        {
            problems.Add(new(CookbookAnnotation, at, message));
            failed = true;
        }
    }

    private static string? ClassBindingOf(MultivectorClassSymbol @class, SemanticModel model)
    {
        var blades = @class.VariableBlades.ToHashSet();
        var fitting = model.ClassBindings.Values
            .Where(b => b.Frame == @class.Frame && b.Coefficients.Select(c => c.Blade.Mask).ToHashSet().SetEquals(blades))
            .OrderBy(b => b.Name, StringComparer.Ordinal)
            .ToList();
        return fitting.FirstOrDefault(b => b.Name == @class.Name + "3D")?.Name ?? (fitting.Count == 1 ? fitting[0].Name : null);
    }

    private static string Identifier(string name) => SyntaxFacts.GetKeywordKind(name) != SyntaxKind.None ? "@" + name : name;

    /// <summary>Generates the binding point as <c>gmac generate</c> does; its counts, or null with the problems reported at the macro.</summary>
    private static Core.CodeGeneration.CodeStatistics? Statistics(GenerationContext context, MacroSymbol macro, string point, List<Diagnostic> problems)
    {
        var generation = BindingPointGenerator.Generate(BindingPointReader.Read(SourceText.FromString(PointPath, point)), context, includeStatistics: false);
        if (generation.Succeeded && generation.Regions is [{ Outcome.Result: { } result }]) return result.Statistics;
        foreach (var d in generation.Diagnostics)
            problems.Add(new(CookbookAnnotation, macro.Declaration, $"the cookbook's binding point of macro '{macro.Name}' does not generate: {d.Code}: {d.Message}"));
        if (generation.Diagnostics.Count == 0)
            problems.Add(new(CookbookAnnotation, macro.Declaration, $"the cookbook's binding point of macro '{macro.Name}' generated no code"));
        return null;
    }
}
