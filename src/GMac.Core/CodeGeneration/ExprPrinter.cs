using System.Globalization;
using System.Text;

namespace GMac.Core.CodeGeneration;

/// <summary>
/// Prints expression trees in the infix syntax shared by C-family languages, with the fewest
/// parentheses that keep the evaluation order of the tree.
/// </summary>
public static class ExprPrinter
{
    private const int SumLevel = 1, ProductLevel = 2, UnaryLevel = 3, PrimaryLevel = 4;

    /// <param name="literal">Prints a constant; by default as a double literal (another scalar type has its own).</param>
    public static string Print(Expr e, Func<string, string> variableText, Func<string, string>? functionName = null, Func<ConstantExpr, string>? literal = null)
    {
        var sb = new StringBuilder();
        Write(sb, e, variableText, functionName ?? (f => f), literal ?? (c => Literal(c.Value)));
        return sb.ToString();
    }

    /// <summary>A double literal that reads back to the same value and is never an integer literal.</summary>
    public static string Literal(double value)
    {
        var text = value.ToString("R", CultureInfo.InvariantCulture);
        if (!text.Contains('.') && !text.Contains('E') && !text.Contains("Infinity") && !text.Contains("NaN")) text += ".0";
        return text;
    }

    private static int Level(Expr e) => e switch
    {
        SumExpr => SumLevel,
        ProductExpr or QuotientExpr => ProductLevel,
        NegateExpr => UnaryLevel,
        ConstantExpr c when c.Value < 0 => UnaryLevel,
        _ => PrimaryLevel,
    };

    private static void Write(StringBuilder sb, Expr e, Func<string, string> variableText, Func<string, string> functionName, Func<ConstantExpr, string> literal)
    {
        switch (e)
        {
            case ConstantExpr c:
                sb.Append(literal(c));
                break;
            case VariableExpr v:
                sb.Append(variableText(v.Name));
                break;
            case SumExpr s:
            {
                // Lead with a positive term where there is one, so "b - a" rather than "-a + b".
                var terms = s.Children.OrderBy(t => IsNegativeTerm(t) ? 1 : 0).ToList();
                for (var i = 0; i < terms.Count; i++)
                {
                    var t = terms[i];
                    if (i == 0)
                    {
                        WriteOperand(sb, t, SumLevel, variableText, functionName, literal);
                        continue;
                    }
                    if (IsNegativeTerm(t))
                    {
                        sb.Append(" - ");
                        WriteOperand(sb, NegatedTerm(t), SumLevel + 1, variableText, functionName, literal);
                    }
                    else
                    {
                        // a nested sum after the first term keeps its own evaluation order: a + (b + c)
                        sb.Append(" + ");
                        WriteOperand(sb, t, SumLevel + 1, variableText, functionName, literal);
                    }
                }
                break;
            }
            case ProductExpr p:
                for (var i = 0; i < p.Children.Count; i++)
                {
                    if (i > 0) sb.Append(" * ");
                    WriteOperand(sb, p.Children[i], i == 0 ? ProductLevel : ProductLevel + 1, variableText, functionName, literal);
                }
                break;
            case QuotientExpr q:
                WriteOperand(sb, q.Numerator, ProductLevel, variableText, functionName, literal);
                sb.Append(" / ");
                WriteOperand(sb, q.Denominator, ProductLevel + 1, variableText, functionName, literal);
                break;
            case NegateExpr n:
                sb.Append('-');
                WriteOperand(sb, n.Operand, n.Operand is NegateExpr or ConstantExpr { Value: < 0 } ? PrimaryLevel + 1 : UnaryLevel, variableText, functionName, literal);
                break;
            case PowerExpr pw:
                sb.Append(functionName("pow")).Append('(');
                Write(sb, pw.Base, variableText, functionName, literal);
                sb.Append(", ").Append(literal(new ConstantExpr(pw.Exponent))).Append(')');
                break;
            case CallExpr call:
                sb.Append(functionName(call.Function)).Append('(');
                for (var i = 0; i < call.Children.Count; i++)
                {
                    if (i > 0) sb.Append(", ");
                    Write(sb, call.Children[i], variableText, functionName, literal);
                }
                sb.Append(')');
                break;
            default:
                throw new InvalidOperationException($"Unknown expression node {e.GetType().Name}.");
        }
    }

    private static bool IsNegativeTerm(Expr t) => t is NegateExpr || t is ConstantExpr { Value: < 0 };

    // The exact value goes with the negated constant, so a float literal is still rounded from it.
    private static Expr NegatedTerm(Expr t) => t is NegateExpr n ? n.Operand
        : (ConstantExpr)t is { Exact: { } r } ? ConstantExpr.From(-r) : new ConstantExpr(-((ConstantExpr)t).Value);

    private static void WriteOperand(StringBuilder sb, Expr e, int minimumLevel, Func<string, string> variableText, Func<string, string> functionName, Func<ConstantExpr, string> literal)
    {
        var parens = Level(e) < minimumLevel;
        if (parens) sb.Append('(');
        Write(sb, e, variableText, functionName, literal);
        if (parens) sb.Append(')');
    }
}
