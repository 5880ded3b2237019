using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Reads an expression tree back as a canonical polynomial when it is one: sums, products,
/// negations and integer powers of variables and exact constants. Anything else (a quotient, a
/// call, a constant rounded to a double) is not lifted, so the caller leaves that tree alone.
/// </summary>
internal static class PolynomialLifting
{
    public static bool TryLift(Expr e, out Scalar polynomial) => TryLift(e, null, out polynomial);

    /// <param name="known">
    /// Lifts already made, by node: a caller that lifts a sum and then the sums inside it (as a
    /// top-down rewrite does when the outer one is kept) lifts each subtree once instead of once
    /// per enclosing sum.
    /// </param>
    public static bool TryLift(Expr e, Dictionary<Expr, Scalar?>? known, out Scalar polynomial)
    {
        polynomial = Scalar.Zero;
        var lifted = Lift(e, known, null);
        if (lifted is null) return false;
        polynomial = lifted;
        return true;
    }

    /// <summary>
    /// Lifts <paramref name="e"/> with each variable that <paramref name="resolve"/> answers for
    /// replaced by that polynomial (a temporary by the polynomial it holds); other variables stay
    /// as they are. Null where <paramref name="e"/> is not a polynomial of those.
    /// </summary>
    public static Scalar? LiftThrough(Expr e, Func<string, Scalar?> resolve) => Lift(e, null, resolve);

    /// <param name="resolve">The polynomial a variable stands for, or null to keep the variable.</param>
    private static Scalar? Lift(Expr e, Dictionary<Expr, Scalar?>? known, Func<string, Scalar?>? resolve)
    {
        if (e.IsLeaf || known is null) return LiftNode(e, known, resolve);
        if (known.TryGetValue(e, out var lifted)) return lifted;
        return known[e] = LiftNode(e, known, resolve);
    }

    private static Scalar? LiftNode(Expr e, Dictionary<Expr, Scalar?>? known, Func<string, Scalar?>? resolve)
    {
        switch (e)
        {
            case ConstantExpr { Exact: { } r }:
                return Scalar.Constant(r);
            case VariableExpr v:
                return resolve?.Invoke(v.Name) ?? Scalar.Variable(v.Name);
            case NegateExpr n:
                return Lift(n.Operand, known, resolve) is { } operand ? -operand : null;
            case PowerExpr { Exponent: > 0 } p:
                return Lift(p.Base, known, resolve) is { } b ? Scalar.IntegerPower(b, p.Exponent) : null;
            case SumExpr s:
            {
                var sum = Scalar.Zero;
                foreach (var c in s.Children)
                {
                    if (Lift(c, known, resolve) is not { } term) return null;
                    sum += term;
                }
                return sum;
            }
            case ProductExpr p:
            {
                var product = Scalar.One;
                foreach (var c in p.Children)
                {
                    if (Lift(c, known, resolve) is not { } factor) return null;
                    product *= factor;
                }
                return product;
            }
            default:
                return null;
        }
    }
}
