using GMac.Core.Numerics;

namespace GMac.Core.CodeGeneration.Accuracy;

/// <summary>
/// Runs a code block on exact rationals: sums, products and quotients exactly, math calls through
/// the caller's <c>call</c> (none without one). Every optimizer pass keeps values in exact
/// arithmetic, so this is the value of the macro itself at the given inputs, whatever the form
/// of the block; the rounding of doubles is what it leaves out.
/// </summary>
public static class ExactEvaluator
{
    /// <summary>
    /// The outputs by name, or null where the block divides by zero, calls a function
    /// <paramref name="call"/> does not answer, or holds verbatim text.
    /// </summary>
    public static IReadOnlyDictionary<string, Rational>? Evaluate(CodeBlock block, IReadOnlyDictionary<string, Rational> inputs,
        Func<string, IReadOnlyList<Rational>, Rational?>? call = null)
    {
        if (block.Statements.Any(s => s is VerbatimStatement)) return null;
        var values = new Dictionary<string, Rational>(inputs, StringComparer.Ordinal);
        var outputs = new Dictionary<string, Rational>(StringComparer.Ordinal);
        foreach (var s in block.Statements.OfType<AssignmentStatement>())
        {
            if (Evaluate(s.Value, values, call) is not { } v) return null;
            values[s.Target] = v;
            if (s.IsOutput) outputs[s.Target] = v;
        }
        return outputs;
    }

    private static Rational? Evaluate(Expr e, IReadOnlyDictionary<string, Rational> values, Func<string, IReadOnlyList<Rational>, Rational?>? call)
    {
        switch (e)
        {
            case ConstantExpr c:
                return c.Exact ?? Rational.FromDouble(c.Value);
            case VariableExpr v:
                return values.TryGetValue(v.Name, out var x) ? x : throw new KeyNotFoundException($"no value for '{v.Name}'");
            case NegateExpr n:
                return Evaluate(n.Operand, values, call) is { } o ? -o : null;
            case SumExpr s:
            {
                var sum = Rational.Zero;
                foreach (var c in s.Children)
                {
                    if (Evaluate(c, values, call) is not { } t) return null;
                    sum += t;
                }
                return sum;
            }
            case ProductExpr p:
            {
                var product = Rational.One;
                foreach (var c in p.Children)
                {
                    if (Evaluate(c, values, call) is not { } f) return null;
                    product *= f;
                }
                return product;
            }
            case QuotientExpr q:
                return Evaluate(q.Numerator, values, call) is { } num && Evaluate(q.Denominator, values, call) is { IsZero: false } den ? num / den : null;
            case PowerExpr pw:
                return Evaluate(pw.Base, values, call) is { } b && !(b.IsZero && pw.Exponent < 0) ? b.Pow(pw.Exponent) : null;
            case CallExpr c:
            {
                if (call is null) return null;
                var args = new Rational[c.Children.Count];
                for (var i = 0; i < args.Length; i++)
                {
                    if (Evaluate(c.Children[i], values, call) is not { } a) return null;
                    args[i] = a;
                }
                return call(c.Function, args);
            }
            default:
                throw new InvalidOperationException($"unknown expression node {e.GetType().Name}");
        }
    }
}
