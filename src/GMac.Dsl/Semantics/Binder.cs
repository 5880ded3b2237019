using Antlr4.Runtime;
using Antlr4.Runtime.Tree;
using GMac.Dsl.Diagnostics;
using GMac.Dsl.Syntax;
using static GMac.Dsl.Syntax.Generated.GMacDslParser;

namespace GMac.Dsl.Semantics;

/// <summary>
/// Turns the syntax trees of a project into a <see cref="SemanticModel"/>.
/// Definitions are collected first and resolved on demand, so their order across
/// files does not matter. Definitions with syntax errors are skipped, and names
/// they would have declared are not reported again as unknown.
/// </summary>
internal sealed partial class Binder
{
    private readonly DiagnosticBag _diagnostics = new();
    private readonly Dictionary<string, FrameSymbol> _frames = new(StringComparer.Ordinal);
    private readonly Dictionary<string, TransformSymbol> _transforms = new(StringComparer.Ordinal);
    private readonly Dictionary<string, ClassBindingSymbol> _bindings = new(StringComparer.Ordinal);
    private readonly Dictionary<string, MacroSymbol> _macros = new(StringComparer.Ordinal);
    private readonly HashSet<string> _brokenNames = new(StringComparer.Ordinal);

    private readonly Dictionary<FrameSymbol, (FrameBodyContext Body, string File)> _frameBodies = [];
    private readonly Dictionary<TransformSymbol, (TransformDefinitionContext Syntax, string File)> _transformBodies = [];
    private readonly HashSet<Symbol> _resolving = [];
    private readonly List<Symbol> _resolvingPath = [];
    private readonly HashSet<Symbol> _resolved = [];

    private string _file = "";

    public static SemanticModel Bind(IReadOnlyList<SyntaxTree> trees)
    {
        var binder = new Binder();
        foreach (var tree in trees) binder._diagnostics.AddRange(tree.Diagnostics);
        binder.BindAll(trees);
        return new SemanticModel(binder._frames, binder._transforms, binder._bindings, binder._macros,
            binder._diagnostics.Items);
    }

    private SourceSpan Span(ParserRuleContext context) => SyntaxTree.SpanOf(_file, context);
    private SourceSpan Span(IToken token) => SyntaxTree.SpanOf(_file, token);

    private void BindAll(IReadOnlyList<SyntaxTree> trees)
    {
        var definitions = new List<(string File, DefinitionContext Syntax)>();
        foreach (var tree in trees)
        {
            if (tree.Root is null) continue;
            foreach (var definition in tree.Root.definition())
            {
                if (IsComplete(definition)) definitions.Add((tree.FilePath, definition));
                else RememberBrokenName(definition);
            }
        }

        // Frames first: everything else is qualified by a frame.
        foreach (var (file, d) in definitions)
            if (d.frameDefinition() is { } f) { _file = file; DeclareFrame(f); }
        foreach (var frame in _frames.Values.ToList()) ResolveFrame(frame);

        foreach (var (file, d) in definitions)
            if (d.transformDefinition() is { } t) { _file = file; DeclareTransform(t); }
        foreach (var transform in _transforms.Values.ToList()) ResolveTransform(transform);

        var members = new List<(string File, ParserRuleContext Syntax, Symbol Symbol)>();
        foreach (var (file, d) in definitions)
        {
            _file = file;
            if (d.subspaceDefinition() is { } s && DeclareMember(s.qualifiedName(), "subspace", (n, sp, f) => new SubspaceSymbol(n, sp, f)) is { } ss)
                members.Add((file, s, ss));
            if (d.classDefinition() is { } c && DeclareMember(c.qualifiedName(), "class", (n, sp, f) => new MultivectorClassSymbol(n, sp, f)) is { } cs)
                members.Add((file, c, cs));
            if (d.constantDefinition() is { } k && DeclareMember(k.qualifiedName(), "constant", (n, sp, f) => new ConstantSymbol(n, sp, f)) is { } ks)
                members.Add((file, k, ks));
        }
        foreach (var (file, syntax, symbol) in members)
            if (symbol is SubspaceSymbol s) { _file = file; BindSubspace((SubspaceDefinitionContext)syntax, s); }
        foreach (var (file, syntax, symbol) in members)
            if (symbol is MultivectorClassSymbol c) { _file = file; BindClass((ClassDefinitionContext)syntax, c); }
        foreach (var (file, syntax, symbol) in members)
            if (symbol is ConstantSymbol k) { _file = file; BindConstant((ConstantDefinitionContext)syntax, k); }

        foreach (var (file, d) in definitions)
            if (d.bindingDefinition() is { } b) { _file = file; BindClassBinding(b); }

        var macros = new List<(string File, MacroDefinitionContext Syntax, MacroSymbol Symbol)>();
        foreach (var (file, d) in definitions)
            if (d.macroDefinition() is { } m) { _file = file; if (DeclareMacro(m) is { } ms) macros.Add((file, m, ms)); }
        foreach (var (file, syntax, symbol) in macros) { _file = file; BindMacroSignature(syntax, symbol); }
        foreach (var (file, syntax, symbol) in macros) { _file = file; BindMacroBody(syntax, symbol); }

        ReportCallCycles();
        ReportUnused();
    }

    /// <summary>A definition is bound only if parsing it needed no recovery. Walked without
    /// recursion: a long flat sum parses as a tree as deep as it is long.</summary>
    private static bool IsComplete(IParseTree root)
    {
        var pending = new Stack<IParseTree>();
        pending.Push(root);
        while (pending.Count > 0)
        {
            var node = pending.Pop();
            if (node is IErrorNode) return false;
            if (node is ParserRuleContext rule)
            {
                if (rule.exception is not null) return false;
                if (rule.Stop is null) return false;
                for (var i = 0; i < rule.ChildCount; i++) pending.Push(rule.GetChild(i));
            }
            else if (node is ITerminalNode terminal && terminal.Symbol.TokenIndex < 0)
            {
                return false; // a token conjured by single-token insertion
            }
        }
        return true;
    }

    private void RememberBrokenName(DefinitionContext definition)
    {
        // The first name-like token after the definition keyword is the defined name.
        var names = new List<string>();
        Collect(definition, names);
        foreach (var n in names) _brokenNames.Add(n);

        static void Collect(IParseTree node, List<string> names)
        {
            if (names.Count >= 4) return;
            if (node is NameContext name) { names.Add(name.GetText()); return; }
            for (var i = 0; i < node.ChildCount; i++) Collect(node.GetChild(i), names);
        }
    }

    private bool IsBroken(string name) => _brokenNames.Contains(name);

    /// <summary>
    /// Candidates compared for "did you mean" hints, over the whole project. Each unknown name is
    /// compared with every name in scope: thousands of both would take minutes. Past the budget,
    /// unknown names are reported without a hint, and binding stays linear in the file's size.
    /// </summary>
    internal const int HintComparisons = 500_000;

    private long _hintComparisonsLeft = HintComparisons;

    private void ReportUnknown(SourceSpan span, string kind, string name, IEnumerable<string> candidates)
    {
        if (IsBroken(name)) return;
        string? hint = null;
        if (_hintComparisonsLeft > 0)
        {
            var list = candidates as IReadOnlyCollection<string> ?? candidates.ToList();
            _hintComparisonsLeft -= list.Count;
            hint = NameSuggester.Suggest(name, list);
        }
        _diagnostics.ReportUnknownName(span, kind, name, hint);
    }

    // ------------------------------------------------------------------ lookups

    private FrameSymbol? LookupFrame(NameContext name)
    {
        var text = name.GetText();
        if (_frames.TryGetValue(text, out var frame))
        {
            frame.IsReferenced = true;
            return frame;
        }
        ReportUnknown(Span(name), "frame", text, _frames.Keys);
        return null;
    }

    /// <summary>Resolves <c>frame.member</c>; <paramref name="defaultFrame"/> allows an unqualified member.</summary>
    private T? LookupMember<T>(QualifiedNameContext qualified, string kind, FrameSymbol? defaultFrame = null) where T : Symbol
    {
        var parts = qualified.name();
        FrameSymbol? frame;
        NameContext memberName;
        if (parts.Length == 1 && defaultFrame is not null)
        {
            frame = defaultFrame;
            memberName = parts[0];
        }
        else if (parts.Length == 2)
        {
            frame = LookupFrame(parts[0]);
            if (frame is null) return null;
            memberName = parts[1];
        }
        else
        {
            _diagnostics.ReportTypeError(Span(qualified), $"expected a {kind} written as frame.name, found '{qualified.GetText()}'");
            return null;
        }

        var text = memberName.GetText();
        if (frame.Members.TryGetValue(text, out var symbol))
        {
            if (symbol is T typed)
            {
                typed.IsReferenced = true;
                return typed;
            }
            _diagnostics.ReportWrongKind(Span(qualified), qualified.GetText(), KindOf(symbol), "a " + kind);
            return null;
        }
        ReportUnknown(Span(memberName), kind, $"{frame.Name}.{text}",
            frame.Members.Values.OfType<T>().Select(s => $"{frame.Name}.{s.Name}"));
        return null;
    }

    private static string KindOf(Symbol symbol) => symbol switch
    {
        FrameSymbol => "a frame",
        SubspaceSymbol => "a subspace",
        MultivectorClassSymbol => "a multivector class",
        ConstantSymbol => "a constant",
        TransformSymbol => "a transform",
        MacroSymbol => "a macro",
        ClassBindingSymbol => "a class binding",
        VariableSymbol => "a multivector variable",
        _ => "something else",
    };

    /// <summary>Parses <c>e1^e2</c> (any order; the sign follows it) or <c>1</c> in a frame.</summary>
    private BladeReference? BindBlade(BladeNameContext blade, FrameSymbol frame)
    {
        if (blade.INT() is { } integer)
        {
            if (integer.GetText() == "1") return new BladeReference(0, 1);
            _diagnostics.ReportTypeError(Span(blade), $"'{integer.GetText()}' is not a blade; the scalar blade is written 1");
            return null;
        }
        var mask = 0;
        var sign = 1;
        foreach (var name in blade.name())
        {
            var index = frame.IndexOfBasis(name.GetText());
            if (index < 0)
            {
                ReportUnknown(Span(name), $"basis vector of frame '{frame.Name}'", name.GetText(), frame.BasisNames);
                return null;
            }
            var bit = 1 << index;
            if ((mask & bit) != 0)
            {
                _diagnostics.ReportTypeError(Span(blade), $"blade '{blade.GetText()}' repeats basis vector '{name.GetText()}'");
                return null;
            }
            // Moving the new vector past every higher-indexed one already present flips the sign.
            if ((System.Numerics.BitOperations.PopCount((uint)(mask & ~((bit << 1) - 1))) & 1) == 1) sign = -sign;
            mask |= bit;
        }
        return new BladeReference(mask, sign);
    }
}
