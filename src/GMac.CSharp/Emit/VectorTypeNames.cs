using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace GMac.CSharp.Emit;

/// <summary>
/// Vector code names its types and their functions the short way (<c>Vector256&lt;double&gt;</c>,
/// <c>Vector256.Sqrt</c>), which compiles only where the file imports their namespace. For a file
/// that does not, every such name is written in full (<c>global::System.Runtime.Intrinsics.Vector256</c>):
/// longer, but the region compiles wherever it is put, and no line outside it is touched.
/// </summary>
public static class VectorTypeNames
{
    /// <summary>
    /// <paramref name="code"/> (statements) with each unqualified use of the vector type's family as a
    /// type or as the class of a function qualified by its namespace; names after a dot (members,
    /// already qualified names) stay as they are.
    /// </summary>
    public static string Qualify(string code, string scalarType)
    {
        if (VectorType.Find(scalarType) is not { } type) return code;
        var root = CSharpSyntaxTree.ParseText(code, new CSharpParseOptions(LanguageVersion.Latest, kind: SourceCodeKind.Script)).GetRoot();
        var starts = root.DescendantNodes()
            .OfType<SimpleNameSyntax>()
            .Where(n => n.Identifier.ValueText == type.Family && !IsAfterDot(n))
            .Select(n => n.SpanStart)
            .OrderDescending()
            .ToList();
        var prefix = $"global::{type.Namespace}.";
        var text = code;
        foreach (var start in starts) text = text.Insert(start, prefix);
        return text;
    }

    private static bool IsAfterDot(SimpleNameSyntax name) => name.Parent switch
    {
        MemberAccessExpressionSyntax m => m.Name == name,
        QualifiedNameSyntax q => q.Right == name,
        AliasQualifiedNameSyntax a => a.Name == name,
        MemberBindingExpressionSyntax => true,
        _ => false,
    };
}
