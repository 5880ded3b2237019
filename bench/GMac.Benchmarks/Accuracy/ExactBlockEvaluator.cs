using GMac.Core.CodeGeneration;
using GMac.Core.Numerics;

namespace GMac.Benchmarks.Accuracy;

/// <summary>
/// Runs a generated code block on exact rationals: sums, products and quotients exactly, math
/// calls through <see cref="HighPrecision"/>. Every optimizer pass keeps values in exact
/// arithmetic, so this is the value of the macro itself at the given inputs, whatever the form
/// of the block; the rounding of doubles is what it leaves out.
/// </summary>
public static class ExactBlockEvaluator
{
    /// <summary>The outputs by name, or null where the block divides by zero or leaves a function's domain.</summary>
    public static IReadOnlyDictionary<string, Rational>? Evaluate(CodeBlock block, IReadOnlyDictionary<string, Rational> inputs)
    {
        var values = new Dictionary<string, Rational>(inputs, StringComparer.Ordinal);
        var outputs = new Dictionary<string, Rational>(StringComparer.Ordinal);
        foreach (var s in block.Statements.OfType<AssignmentStatement>())
        {
            if (Evaluate(s.Value, values) is not { } v) return null;
            values[s.Target] = v;
            if (s.IsOutput) outputs[s.Target] = v;
        }
        return outputs;
    }

    private static Rational? Evaluate(Expr e, IReadOnlyDictionary<string, Rational> values)
    {
        switch (e)
        {
            case ConstantExpr c:
                return c.Exact ?? Rational.FromDouble(c.Value);
            case VariableExpr v:
                return values.TryGetValue(v.Name, out var x) ? x : throw new KeyNotFoundException($"no value for '{v.Name}'");
            case NegateExpr n:
                return Evaluate(n.Operand, values) is { } o ? -o : null;
            case SumExpr s:
            {
                var sum = Rational.Zero;
                foreach (var c in s.Children)
                {
                    if (Evaluate(c, values) is not { } t) return null;
                    sum += t;
                }
                return sum;
            }
            case ProductExpr p:
            {
                var product = Rational.One;
                foreach (var c in p.Children)
                {
                    if (Evaluate(c, values) is not { } f) return null;
                    product *= f;
                }
                return product;
            }
            case QuotientExpr q:
                return Evaluate(q.Numerator, values) is { } num && Evaluate(q.Denominator, values) is { IsZero: false } den ? num / den : null;
            case PowerExpr pw:
                return Evaluate(pw.Base, values) is { } b && !(b.IsZero && pw.Exponent < 0) ? b.Pow(pw.Exponent) : null;
            case CallExpr call:
            {
                var args = new Rational[call.Children.Count];
                for (var i = 0; i < args.Length; i++)
                {
                    if (Evaluate(call.Children[i], values) is not { } a) return null;
                    args[i] = a;
                }
                return HighPrecision.Call(call.Function, args);
            }
            default:
                throw new InvalidOperationException($"unknown expression node {e.GetType().Name}");
        }
    }
}
