using System.Collections.Concurrent;
using GMac.CSharp.BindingPoints;
using GMac.CSharp.Emit;
using GMac.Core.CodeGeneration;
using GMac.Dsl;
using GMac.Dsl.Diagnostics;
using GMac.Dsl.Semantics;

namespace GMac.Cli.LanguageServer;

/// <summary>
/// One version of the DSL folders bound together: the texts (open documents over the files on
/// disk), the project, its diagnostics as <c>gmac check</c> prints them, and the code generated
/// for its macros, computed on first demand and kept as long as this version is current.
/// </summary>
internal sealed class Analysis
{
    private readonly ConcurrentDictionary<string, Lazy<MacroCode>> _generated = new(StringComparer.Ordinal);
    private readonly Lazy<GenerationContext?> _context;
    // One generation at a time: the generator and its simplification cache are shared.
    private readonly Lock _generation = new();

    public Analysis(int version, IReadOnlyList<(string Path, string Text)> sources)
    {
        Version = version;
        Texts = sources.ToDictionary(s => s.Path, s => new SourceText(s.Path, s.Text), StringComparer.Ordinal);
        Project = DslProject.FromSources(sources);
        Diagnostics = OutputBlockCheck.Diagnostics(Project);
        _context = new Lazy<GenerationContext?>(() => Diagnostics.Any(d => d.IsError) ? null : new GenerationContext(Project, cacheDirectory: null));
    }

    public int Version { get; }
    public IReadOnlyDictionary<string, SourceText> Texts { get; }
    public DslProject Project { get; }
    public IReadOnlyList<Diagnostic> Diagnostics { get; }
    public SemanticModel Model => Project.Model;

    /// <summary>Every named definition: frames, their members, transforms, bindings, macros.</summary>
    public IEnumerable<Symbol> Definitions =>
        Model.Frames.Values.Cast<Symbol>()
            .Concat(Model.Frames.Values.SelectMany(f => f.MemberSymbols.Where(m => m is not MultivectorClassSymbol { IsImplicit: true })))
            .Concat(Model.Transforms.Values).Concat(Model.ClassBindings.Values).Concat(Model.Macros.Values);

    /// <summary>The definition an identifier names: <c>F.M</c> a member of frame F, else a frame, macro, binding or transform.</summary>
    public Symbol? Resolve(SourceText text, (int Start, int Length) token)
    {
        var name = text[token];
        if (text.QualifierOf(token.Start) is { } qualifier)
        {
            var frameName = text[qualifier];
            return Model.Frames.TryGetValue(frameName, out var f) ? Model.FindMember(frameName, name) : null;
        }
        if (Model.Frames.TryGetValue(name, out var frame)) return frame;
        if (Model.Macros.TryGetValue(name, out var macro)) return macro;
        if (Model.ClassBindings.TryGetValue(name, out var binding)) return binding;
        return Model.Transforms.TryGetValue(name, out var transform) ? transform : null;
    }

    /// <summary>The name token of a definition: the last identifier of its declaration span (<c>Vector</c> of <c>e3d.Vector</c>).</summary>
    public Location? NameLocation(Symbol symbol, Func<string, string> uriOf)
    {
        var span = symbol.Declaration;
        if (!Texts.TryGetValue(span.FilePath, out var text)) return null;
        var start = text.OffsetOf(span.Line, span.Column);
        var end = start + Math.Max(span.Length, 1);
        var name = text.Identifiers.LastOrDefault(t => t.Start >= start && t.Start < end && text[t] == symbol.Name);
        return name.Length > 0
            ? new Location(uriOf(text.Path), text.RangeOf(name.Start, name.Length))
            : new Location(uriOf(text.Path), text.RangeOf(start, text.TokenLengthAt(start)));
    }

    /// <summary>Every identifier of every file that names <paramref name="symbol"/> (its declaration included).</summary>
    public IEnumerable<(SourceText Text, (int Start, int Length) Token)> References(Symbol symbol) =>
        Texts.Values.SelectMany(t => t.Identifiers.Where(id => t.Text.AsSpan(id.Start, id.Length).SequenceEqual(symbol.Name) && ReferenceEquals(Resolve(t, id), symbol))
            .Select(id => (t, id)));

    /// <summary>The macro's code for default bindings, generated once for this version (null when the DSL has errors).</summary>
    public MacroCode? Generated(MacroSymbol macro, CancellationToken cancellation)
    {
        if (_context.Value is not { } context) return null;
        cancellation.ThrowIfCancellationRequested();
        return _generated.GetOrAdd(macro.Name, name => new Lazy<MacroCode>(() => Generate(context, name))).Value;
    }

    private MacroCode Generate(GenerationContext context, string macro)
    {
        lock (_generation)
        {
            try
            {
                var specs = context.Generator.DefaultBindings(macro).Select(d => d with { Line = 0 }).ToList();
                var (outcome, code, problem) = MacroGeneration.GenerateCode(context, macro, specs, 0, filePath: "", generated => new CSharpEmitOptions
                {
                    NewLine = "\n",
                    DeclareOutputs = generated.Plan?.DefaultOutputs ?? false,
                    MayOverwrite = BindingExpressions.Overwrites(generated.Result!.Block),
                });
                if (!outcome.Succeeded) return new MacroCode(null, null, string.Join("\n", outcome.Errors.Select(e => e.Message)));
                if (problem is { } p) return new MacroCode(null, null, p.Message);
                return new MacroCode(outcome.Result!.Block.Statistics(), code, null);
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                return new MacroCode(null, null, $"internal error while generating '{macro}': {e.GetType().Name}: {e.Message}");
            }
        }
    }
}
