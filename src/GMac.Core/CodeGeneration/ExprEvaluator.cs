namespace GMac.Core.CodeGeneration;

/// <summary>Numeric evaluation of an expression tree.</summary>
public static class ExprEvaluator
{
    public static double Evaluate(Expr e, IReadOnlyDictionary<string, double> variables) => e switch
    {
        ConstantExpr c => c.Value,
        VariableExpr v => variables.TryGetValue(v.Name, out var x) ? x : throw new KeyNotFoundException($"No value for '{v.Name}'."),
        SumExpr s => s.Children.Sum(c => Evaluate(c, variables)),
        ProductExpr p => p.Children.Aggregate(1.0, (acc, c) => acc * Evaluate(c, variables)),
        QuotientExpr q => Evaluate(q.Numerator, variables) / Evaluate(q.Denominator, variables),
        NegateExpr n => -Evaluate(n.Operand, variables),
        PowerExpr p => Math.Pow(Evaluate(p.Base, variables), p.Exponent),
        CallExpr c => MathFunctions.TryEvaluate(c.Function, c.Children.Select(a => Evaluate(a, variables)).ToArray(), out var r) ? r : double.NaN,
        _ => throw new InvalidOperationException($"Unknown expression node {e.GetType().Name}."),
    };
}
