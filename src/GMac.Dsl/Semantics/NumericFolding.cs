using GMac.Dsl.Compilation;

namespace GMac.Dsl.Semantics;

/// <summary>
/// Floating-point value of a constant scalar expression (numbers, arithmetic, scalar functions
/// of constants), used to catch constants with no real value, such as sqrt(-4) or log(0), that
/// would otherwise be generated as code computing NaN. Null when the expression is not constant.
/// </summary>
internal static class NumericFolding
{
    public static double? TryEvaluate(BoundExpression expression)
    {
        switch (expression)
        {
            case BoundNumber n:
                return n.Value.ToDouble();
            case BoundUnaryOperation { Operator: UnaryOperator.Negate } u:
                return -TryEvaluate(u.Operand);
            case BoundBinaryOperation b when b.Type.IsScalar:
            {
                if (TryEvaluate(b.Left) is not { } l || TryEvaluate(b.Right) is not { } r) return null;
                return b.Operator switch
                {
                    BinaryOperator.Add => l + r,
                    BinaryOperator.Subtract => l - r,
                    BinaryOperator.Multiply or BinaryOperator.Gp => l * r,
                    BinaryOperator.Divide => l / r,
                    BinaryOperator.Power => Math.Pow(l, r),
                    _ => null,
                };
            }
            case BoundScalarFunctionCall call:
            {
                var args = new double[call.Arguments.Count];
                for (var i = 0; i < args.Length; i++)
                {
                    if (TryEvaluate(call.Arguments[i]) is not { } a) return null;
                    args[i] = a;
                }
                return ScalarFunctions.TryApply(call.Function, args, DoubleDomain.Instance, out var value) ? value : null;
            }
            default:
                return null;
        }
    }
}
