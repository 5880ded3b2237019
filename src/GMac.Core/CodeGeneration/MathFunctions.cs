namespace GMac.Core.CodeGeneration;

/// <summary>The neutral math functions a code block may call, with their numeric meaning for folding.</summary>
public static class MathFunctions
{
    public static readonly IReadOnlySet<string> Names = new HashSet<string>(StringComparer.Ordinal)
    {
        "sin", "cos", "tan", "acos", "sqrt", "exp", "log", "atan2", "abs", "pow", "sinh", "cosh",
    };

    public static bool TryEvaluate(string function, double[] args, out double value)
    {
        value = function switch
        {
            "sin" when args.Length == 1 => Math.Sin(args[0]),
            "cos" when args.Length == 1 => Math.Cos(args[0]),
            "tan" when args.Length == 1 => Math.Tan(args[0]),
            "acos" when args.Length == 1 => Math.Acos(args[0]),
            "sqrt" when args.Length == 1 => Math.Sqrt(args[0]),
            "exp" when args.Length == 1 => Math.Exp(args[0]),
            "log" when args.Length == 1 => Math.Log(args[0]),
            "abs" when args.Length == 1 => Math.Abs(args[0]),
            "sinh" when args.Length == 1 => Math.Sinh(args[0]),
            "cosh" when args.Length == 1 => Math.Cosh(args[0]),
            "atan2" when args.Length == 2 => Math.Atan2(args[0], args[1]),
            "pow" when args.Length == 2 => Math.Pow(args[0], args[1]),
            _ => double.NaN,
        };
        return double.IsFinite(value);
    }
}
