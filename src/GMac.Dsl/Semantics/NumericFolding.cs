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
                return Apply(call.Function, args);
            }
            default:
                return null;
        }
    }

    private static double Apply(ScalarFunction function, double[] a) => function switch
    {
        ScalarFunction.Pi => Math.PI,
        ScalarFunction.Sin => Math.Sin(a[0]),
        ScalarFunction.Cos => Math.Cos(a[0]),
        ScalarFunction.Tan => Math.Tan(a[0]),
        ScalarFunction.Asin => Math.Asin(a[0]),
        ScalarFunction.Acos => Math.Acos(a[0]),
        ScalarFunction.Atan => Math.Atan(a[0]),
        ScalarFunction.Atan2 => Math.Atan2(a[0], a[1]),
        ScalarFunction.Sinh => Math.Sinh(a[0]),
        ScalarFunction.Cosh => Math.Cosh(a[0]),
        ScalarFunction.Tanh => Math.Tanh(a[0]),
        ScalarFunction.Sqrt => Math.Sqrt(a[0]),
        ScalarFunction.Exp => Math.Exp(a[0]),
        ScalarFunction.Log => Math.Log(a[0]),
        ScalarFunction.Abs => Math.Abs(a[0]),
        _ => double.NaN,
    };
}
