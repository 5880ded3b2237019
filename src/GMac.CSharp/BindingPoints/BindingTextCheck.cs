using GMac.Dsl.Generation;
using GMac.Dsl.Semantics;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;
using Diagnostic = GMac.Dsl.Diagnostics.Diagnostic;
using DiagnosticCodes = GMac.Dsl.Diagnostics.DiagnosticCodes;
using DiagnosticDescriptor = GMac.Dsl.Diagnostics.DiagnosticDescriptor;
using SourceSpan = GMac.Dsl.Diagnostics.SourceSpan;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// The C# text of bindings is pasted into generated code, so before generating it must be exactly
/// one C# expression (one assignable expression where an output is written): a fragment such as
/// <c>1+</c> or <c>x); Evil(); (0</c> would otherwise become broken or extra statements.
/// </summary>
internal static class BindingTextCheck
{
    /// <summary>One error per binding whose C# text cannot be pasted as it is, at the binding's line and column.</summary>
    public static List<Diagnostic> Check(MacroSymbol macro, IEnumerable<BindingSpec> specs, string filePath)
    {
        var outputs = macro.Outputs.Select(o => o.Name).ToHashSet(StringComparer.Ordinal);
        var errors = new List<Diagnostic>();
        foreach (var spec in specs)
        {
            var problem = spec switch
            {
                CoefficientBindingSpec c when outputs.Contains(c.Parameter) => OutputProblem(c.Parameter, c.Value.Target, c.Value.Text),
                CoefficientBindingSpec c => InputProblem(c),
                ClassBindingSpec c => ObjectProblem(c.Target) is { } objectProblem ? (DiagnosticCodes.NotAnExpression, objectProblem)
                    : outputs.Contains(c.Parameter) ? OutputProblem(c.Parameter, c.Target.Trim(), c.Target) : null,
                _ => null,
            };
            if (problem is { } p) errors.Add(new Diagnostic(p.Descriptor, SourceSpan.At(filePath, spec.Line, spec.Column), p.Message));
        }
        return errors;
    }

    private static (DiagnosticDescriptor Descriptor, string Message)? OutputProblem(string parameter, string? target, string text)
    {
        if (target is not null && ExpressionProblem(target) is { } problem)
            return (DiagnosticCodes.NotAnExpression, $"the target '{target}' of output '{parameter}' is not one C# expression: {problem}");
        if (target is null || !IsAssignable(target))
            return (DiagnosticCodes.TargetNotAssignable, $"output '{parameter}' is bound to '{text}', which cannot be assigned; use a variable, field, property or element, e.g. \"<w.x>\"");
        // Each coefficient is a separate assignment: a call or increment in the target would run at each one.
        if (BindingExpressions.HasEffects(target))
            return (DiagnosticCodes.TargetHasEffects, $"the target '{target}' of output '{parameter}' would be evaluated at every coefficient written (it calls, assigns or increments); bind a variable and copy it afterwards");
        return null;
    }

    /// <summary>Each hole of a template, or the whole of a bare value that is not a number.</summary>
    private static (DiagnosticDescriptor Descriptor, string Message)? InputProblem(CoefficientBindingSpec c)
    {
        var parts = c.Value switch
        {
            TemplateValue t => t.Holes.Select(h => h.Text).ToList(),
            HostExpression h => [h.Text],
            _ => new List<string>(),
        };
        foreach (var part in parts)
            if (ExpressionProblem(part) is { } problem)
                return (DiagnosticCodes.NotAnExpression, $"'{part.Trim()}' bound to input '{c.Parameter}' is not one C# expression: {problem}");
        return null;
    }

    /// <summary>A class binding reads <c>obj.member</c>: the object must stay whole when a member access follows it.</summary>
    private static string? ObjectProblem(string target)
    {
        if (ExpressionProblem(target) is { } problem) return $"the object '{target.Trim()}' is not one C# expression: {problem}";
        var access = SyntaxFactory.ParseExpression(target.Trim() + ".member");
        return access is MemberAccessExpressionSyntax m && m.Expression.ToString() == target.Trim()
            ? null
            : $"the object '{target.Trim()}' must be a name, member, element or call (put parentheses around other expressions)";
    }

    /// <summary>Null when <paramref name="text"/> is exactly one expression with nothing around or inside it but spaces.</summary>
    private static string? ExpressionProblem(string text)
    {
        var expression = SyntaxFactory.ParseExpression(text, consumeFullText: true);
        if (expression.GetDiagnostics().FirstOrDefault(d => d.Severity == DiagnosticSeverity.Error) is { } error) return error.GetMessage();
        // A comment or line break would swallow or split the generated statement around the text.
        if (expression.DescendantTrivia(descendIntoTrivia: true).Any(t => !t.IsKind(SyntaxKind.WhitespaceTrivia)))
            return "comments, line breaks and directives are not allowed";
        return null;
    }

    /// <summary>A variable, field, property or element: something C# lets the generated code assign to.</summary>
    public static bool IsAssignable(string text)
    {
        var expression = SyntaxFactory.ParseExpression(text);
        if (expression.ContainsDiagnostics) return false;
        while (expression is ParenthesizedExpressionSyntax p) expression = p.Expression;
        return expression is IdentifierNameSyntax or ElementAccessExpressionSyntax
            || expression is MemberAccessExpressionSyntax m && m.IsKind(SyntaxKind.SimpleMemberAccessExpression) || expression.IsKind(SyntaxKind.PointerMemberAccessExpression);
    }
}
