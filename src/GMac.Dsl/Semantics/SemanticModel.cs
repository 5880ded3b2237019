using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary>Everything a GMacDSL project defines, resolved and checked.</summary>
public sealed class SemanticModel
{
    internal SemanticModel(
        IReadOnlyDictionary<string, FrameSymbol> frames,
        IReadOnlyDictionary<string, TransformSymbol> transforms,
        IReadOnlyDictionary<string, ClassBindingSymbol> bindings,
        IReadOnlyDictionary<string, MacroSymbol> macros,
        IReadOnlyList<Diagnostic> diagnostics)
    {
        Frames = frames;
        Transforms = transforms;
        ClassBindings = bindings;
        Macros = macros;
        Diagnostics = diagnostics;
    }

    public IReadOnlyDictionary<string, FrameSymbol> Frames { get; }
    public IReadOnlyDictionary<string, TransformSymbol> Transforms { get; }
    public IReadOnlyDictionary<string, ClassBindingSymbol> ClassBindings { get; }
    public IReadOnlyDictionary<string, MacroSymbol> Macros { get; }
    public IReadOnlyList<Diagnostic> Diagnostics { get; }

    public IEnumerable<SubspaceSymbol> Subspaces => Frames.Values.SelectMany(f => f.MemberSymbols.OfType<SubspaceSymbol>());
    public IEnumerable<MultivectorClassSymbol> Classes => Frames.Values.SelectMany(f => f.MemberSymbols.OfType<MultivectorClassSymbol>());
    public IEnumerable<ConstantSymbol> Constants => Frames.Values.SelectMany(f => f.MemberSymbols.OfType<ConstantSymbol>());

    /// <summary>Looks up <c>frame.member</c> (a subspace, class or constant).</summary>
    public Symbol? FindMember(string frame, string member) =>
        Frames.TryGetValue(frame, out var f) && f.Members.TryGetValue(member, out var s) ? s : null;

    public MultivectorClassSymbol? FindClass(string qualifiedName)
    {
        var dot = qualifiedName.IndexOf('.');
        return dot < 0 ? null : FindMember(qualifiedName[..dot], qualifiedName[(dot + 1)..]) as MultivectorClassSymbol;
    }
}
