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
        return _byMember[id] = new RegionScope(id, names);
    }

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
