using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Reads an expression tree back as a canonical polynomial when it is one: sums, products,
/// negations and integer powers of variables and exact constants. Anything else (a quotient, a
/// call, a constant rounded to a double) is not lifted, so the caller leaves that tree alone.
/// </summary>
internal static class PolynomialLifting
{
    public static bool TryLift(Expr e, out Scalar polynomial)
    {
        polynomial = Scalar.Zero;
        var lifted = Lift(e);
        if (lifted is null) return false;
        polynomial = lifted;
        return true;
    }

    private static Scalar? Lift(Expr e)
    {
        switch (e)
        {
            case ConstantExpr { Exact: { } r }:
                return Scalar.Constant(r);
            case VariableExpr v:
                return Scalar.Variable(v.Name);
            case NegateExpr n:
                return Lift(n.Operand) is { } operand ? -operand : null;
            case PowerExpr { Exponent: > 0 } p:
                return Lift(p.Base) is { } b ? Scalar.IntegerPower(b, p.Exponent) : null;
            case SumExpr s:
            {
                var sum = Scalar.Zero;
                foreach (var c in s.Children)
                {
                    if (Lift(c) is not { } term) return null;
                    sum += term;
                }
                return sum;
            }
            case ProductExpr p:
            {
                var product = Scalar.One;
                foreach (var c in p.Children)
                {
                    if (Lift(c) is not { } factor) return null;
                    product *= factor;
                }
                return product;
            }
            default:
                return null;
        }
    }
}
