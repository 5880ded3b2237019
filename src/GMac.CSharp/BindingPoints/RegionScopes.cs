using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// Finds the scope of each region of a file: the type member holding it (its locals, parameters
/// and the names it uses) plus the members of the types around it. A region outside any member
/// (top-level statements) gets the whole file. Region bodies are left out: they are regenerated.
/// </summary>
internal sealed class RegionScopes(SyntaxNode root, IReadOnlyList<(int Start, int End)> bodies)
{
    private readonly Dictionary<int, RegionScope> _byMember = [];

    /// <summary>The scope of the region whose <c>#region</c> directive starts at <paramref name="position"/>.</summary>
    public RegionScope Of(int position)
    {
        var token = root.FindToken(position);
        var member = token.Parent?.AncestorsAndSelf()
            .FirstOrDefault(n => n is MemberDeclarationSyntax and not BaseTypeDeclarationSyntax && n.Parent is TypeDeclarationSyntax);
        var node = member ?? root;
        var id = member?.SpanStart ?? -1;
        if (_byMember.TryGetValue(id, out var scope)) return scope;
        var names = Identifiers(node);
        foreach (var type in node.AncestorsAndSelf().OfType<TypeDeclarationSyntax>())
            names.UnionWith(DeclaredNames(type));
        var (parameters, locals, plain) = (new HashSet<string>(StringComparer.Ordinal), new HashSet<string>(StringComparer.Ordinal), new HashSet<string>(StringComparer.Ordinal));
        Classify(node.DescendantNodesAndSelf(), parameters, locals, plain);
        // Around the member: primary-constructor parameters and fields (a pointer or ref field may point anywhere).
        foreach (var type in node.AncestorsAndSelf().OfType<TypeDeclarationSyntax>())
            Classify([.. type.ParameterList?.Parameters ?? [], .. type.Members.OfType<BaseFieldDeclarationSyntax>().Select(f => f.Declaration)], locals, locals, []);
        return _byMember[id] = new RegionScope(id, names) { Storage = new StorageNames(parameters, locals, plain) };
    }

    /// <summary>
    /// Sorts declared names: parameters by reference (ref, in, out) or of pointer or span type; locals
    /// of such kinds (ref locals, pointers, spans, addresses); plain locals and by-value parameters.
    /// </summary>
    private static void Classify(IEnumerable<SyntaxNode> nodes, HashSet<string> referenceParameters, HashSet<string> referenceLocals, HashSet<string> plain)
    {
        foreach (var n in nodes)
        {
            switch (n)
            {
                case ParameterSyntax p:
                    (p.Modifiers.Any(m => m.Kind() is SyntaxKind.RefKeyword or SyntaxKind.OutKeyword or SyntaxKind.InKeyword) || IsReferenceLike(p.Type) ? referenceParameters : plain)
                        .Add(p.Identifier.ValueText);
                    break;
                case VariableDeclarationSyntax d:
                    foreach (var v in d.Variables)
                        (IsReferenceLike(d.Type) || v.Initializer?.Value is RefExpressionSyntax or StackAllocArrayCreationExpressionSyntax
                            || v.Initializer?.Value is PrefixUnaryExpressionSyntax { RawKind: (int)SyntaxKind.AddressOfExpression } ? referenceLocals : plain)
                            .Add(v.Identifier.ValueText);
                    break;
                case ForEachStatementSyntax f:
                    (IsReferenceLike(f.Type) ? referenceLocals : plain).Add(f.Identifier.ValueText);
                    break;
            }
        }
    }

    private static bool IsReferenceLike(TypeSyntax? type) => type switch
    {
        RefTypeSyntax or PointerTypeSyntax or FunctionPointerTypeSyntax => true,
        ScopedTypeSyntax => true,
        QualifiedNameSyntax q => IsReferenceLike(q.Right),
        GenericNameSyntax g => g.Identifier.ValueText.EndsWith("Span", StringComparison.Ordinal) || g.Identifier.ValueText.EndsWith("Memory", StringComparison.Ordinal),
        _ => false,
    };

    private HashSet<string> Identifiers(SyntaxNode node) => node.DescendantTokens()
        .Where(t => t.IsKind(SyntaxKind.IdentifierToken) && !bodies.Any(b => t.SpanStart >= b.Start && t.SpanStart < b.End))
        .Select(t => t.ValueText)
        .ToHashSet(StringComparer.Ordinal);

    /// <summary>The type's own name, its type and primary-constructor parameters, and the names of its members.</summary>
    private static IEnumerable<string> DeclaredNames(TypeDeclarationSyntax type)
    {
        yield return type.Identifier.ValueText;
        foreach (var p in type.TypeParameterList?.Parameters ?? default) yield return p.Identifier.ValueText;
        foreach (var p in type.ParameterList?.Parameters ?? default) yield return p.Identifier.ValueText;
        foreach (var member in type.Members)
        {
            switch (member)
            {
                case BaseFieldDeclarationSyntax f:
                    foreach (var v in f.Declaration.Variables) yield return v.Identifier.ValueText;
                    break;
                case PropertyDeclarationSyntax p:
                    yield return p.Identifier.ValueText;
                    break;
                case EventDeclarationSyntax e:
                    yield return e.Identifier.ValueText;
                    break;
                case MethodDeclarationSyntax m:
                    yield return m.Identifier.ValueText;
                    break;
                case BaseTypeDeclarationSyntax t:
                    yield return t.Identifier.ValueText;
                    break;
                case DelegateDeclarationSyntax d:
                    yield return d.Identifier.ValueText;
                    break;
            }
        }
    }
}
