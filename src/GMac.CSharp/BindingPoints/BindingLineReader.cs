using System.Text.RegularExpressions;
using GMac.Core.Numerics;
using GMac.Dsl.Generation;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// Reads one <c>//GMac.Bind(…);</c>, <c>//GMac.AssumeMin(…);</c>, <c>//GMac.AssumeMax(…);</c> or
/// <c>//GMac.Type("float");</c>, <c>//GMac.Fma(true);</c> or <c>//GMac.Batch("i");</c> line as the C# invocation it looks like, so string escapes and verbatim strings mean what they
/// mean in C#. A string-literal value is a template (its <c>&lt;…&gt;</c> parts are C# text); any
/// other expression is bare C#. This is the one reader of the syntax: gmac and the benchmark
/// report both go through it.
/// </summary>
public static partial class BindingLineReader
{
    public const string LinePrefix = "//GMac.";

    /// <summary>Whether <paramref name="sourceLine"/>, after its indentation, is a binding line.</summary>
    public static bool IsBindingLine(string sourceLine) => sourceLine.TrimStart().StartsWith(LinePrefix, StringComparison.Ordinal);

    /// <summary>
    /// Reads a line of a C# file (its terminator may be included); null when it is not a binding
    /// line, an error result when it only looks like one (<c>// GMac.Bind</c>). <paramref name="lineNumber"/> is 1-based and goes into the spec for diagnostics.
    /// </summary>
    public static BindingLineResult? Read(string sourceLine, int lineNumber)
    {
        var text = sourceLine.TrimEnd('\r', '\n');
        var trimmed = text.TrimStart();
        var column = text.Length - trimmed.Length + 1;
        if (!trimmed.StartsWith(LinePrefix, StringComparison.Ordinal))
        {
            // Deleted with the generated code, such a line would lose its binding without a word.
            return NearMiss().IsMatch(trimmed)
                ? new BindingLineResult(lineNumber, column, null, $"'{trimmed.TrimEnd()}' looks like a GMac line but is not one: a GMac line starts exactly with '{LinePrefix}' (two slashes, no space, that case)")
                : null;
        }
        var spec = ReadCall(trimmed[2..], lineNumber, column, out var error);
        return new BindingLineResult(lineNumber, column, spec, error);
    }

    private static BindingSpec? ReadCall(string code, int line, int column, out string? error)
    {
        error = null;
        var expression = SyntaxFactory.ParseExpression(code, consumeFullText: false);
        var rest = code[expression.FullSpan.End..];
        if (expression.ContainsDiagnostics || !IsLineRest(rest))
        {
            var first = expression.GetDiagnostics().FirstOrDefault()?.GetMessage();
            error = $"malformed binding line '//{code.Trim()}'{(first is null ? "" : $": {first}")}; expected e.g. //GMac.Bind(\"u.e1\", \"<u.x>\");";
            return null;
        }
        if (expression is not InvocationExpressionSyntax
            {
                Expression: MemberAccessExpressionSyntax { Expression: IdentifierNameSyntax { Identifier.ValueText: "GMac" } } member,
            } call)
        {
            error = $"'//{code.Trim()}' is not a call of GMac.Bind, GMac.AssumeMin, GMac.AssumeMax, GMac.Type, GMac.Fma or GMac.Batch";
            return null;
        }
        var args = call.ArgumentList.Arguments;
        var command = member.Name.Identifier.ValueText;
        switch (command)
        {
            case "Bind" when args.Count == 2:
            {
                var name = StringValue(args[0]);
                var dot = name?.IndexOf('.') ?? -1;
                if (name is null || dot <= 0 || dot == name.Length - 1)
                {
                    error = "the first argument of a two-argument GMac.Bind must be a string \"parameter.blade\", such as \"v.e1\" or \"angle.1\"";
                    return null;
                }
                var value = StringValue(args[1]);
                var text = value ?? args[1].Expression.ToString();
                return new CoefficientBindingSpec(name[..dot].Trim(), name[(dot + 1)..].Trim(), BindingValueReader.Read(text, quoted: value is not null), line, column);
            }
            case "Bind" when args.Count == 3:
            {
                var parameter = StringValue(args[0]);
                var binding = StringValue(args[1]);
                if (parameter is null || binding is null || parameter.Contains('.'))
                {
                    error = "a three-argument GMac.Bind takes a parameter name and a class binding name as strings, then the C# object, e.g. GMac.Bind(\"u\", \"Vector3D\", \"u\")";
                    return null;
                }
                var target = StringValue(args[2]) ?? args[2].Expression.ToString();
                return BindingValueReader.ClassBinding(parameter.Trim(), binding.Trim(), target, line, column);
            }
            case "Bind":
                error = $"GMac.Bind takes 2 or 3 arguments, not {args.Count}";
                return null;
            case "AssumeMin" or "AssumeMax" when args.Count == 2:
            {
                var subject = StringValue(args[0]) ?? args[0].Expression.ToString();
                var boundText = StringValue(args[1]) ?? args[1].Expression.ToString();
                if (!Rational.TryParse(boundText.Replace(" ", ""), out var bound))
                {
                    error = $"the bound '{boundText}' of GMac.{command} is not a number";
                    return null;
                }
                return new AssumptionSpec(subject, bound, command == "AssumeMin", line, column);
            }
            case "AssumeMin" or "AssumeMax":
                error = $"GMac.{command} takes 2 arguments (expression, bound), not {args.Count}";
                return null;
            case "Type" when args.Count == 1 && StringValue(args[0]) is { } typeName:
                return new ScalarTypeSpec(typeName.Trim(), line, column);
            case "Type":
                error = "GMac.Type takes one string, the scalar type of the code: GMac.Type(\"float\") or GMac.Type(\"double\")";
                return null;
            case "Fma" when args.Count == 1:
            {
                var argument = args[0].Expression;
                bool? enabled = argument.Kind() switch
                {
                    SyntaxKind.TrueLiteralExpression => true,
                    SyntaxKind.FalseLiteralExpression => false,
                    _ => null,
                };
                // Any other value is reported where the region is generated, under its own code.
                return new FusedMultiplyAddSpec(enabled, argument.ToString(), line, column);
            }
            case "Fma":
                error = $"GMac.Fma takes one argument, true or false, not {args.Count}: GMac.Fma(true) fuses products into the sums they are added to";
                return null;
            case "Batch" when args.Count == 1 && StringValue(args[0]) is { } index && SyntaxFacts.IsValidIdentifier(index.Trim())
                && SyntaxFacts.GetKeywordKind(index.Trim()) == SyntaxKind.None:
                return new BatchSpec(index.Trim(), line, column);
            case "Batch":
                error = "GMac.Batch takes one string, the name of the item index the bindings read spans at: GMac.Batch(\"i\") with GMac.Bind(\"u.e1\", \"<ux[i]>\")";
                return null;
            default:
                error = $"unknown binding command 'GMac.{command}'; expected Bind, AssumeMin, AssumeMax, Type, Fma or Batch";
                return null;
        }
    }

    /// <summary>What may follow the call on its line: an optional semicolon and a comment.</summary>
    private static bool IsLineRest(string rest)
    {
        var t = rest.Trim();
        if (t.StartsWith(';')) t = t[1..].TrimStart();
        return t.Length == 0 || t.StartsWith("//", StringComparison.Ordinal);
    }

    /// <summary>A comment that starts like a GMac line with other slashes, spaces or case: <c>// GMac.</c>, <c>///GMac.</c>, <c>//Gmac.</c>.</summary>
    [GeneratedRegex(@"^/{2,}\s*gmac\s*\.", RegexOptions.IgnoreCase | RegexOptions.CultureInvariant)]
    private static partial Regex NearMiss();

    private static string? StringValue(ArgumentSyntax argument) =>
        argument.Expression is LiteralExpressionSyntax literal && literal.IsKind(SyntaxKind.StringLiteralExpression) ? literal.Token.ValueText : null;
}
