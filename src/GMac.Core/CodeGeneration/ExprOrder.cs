namespace GMac.Core.CodeGeneration;

/// <summary>A deterministic total order on expression trees (hash first, structure on ties), without printing.</summary>
internal static class ExprOrder
{
    public static int Compare(Expr a, Expr b)
    {
        if (ReferenceEquals(a, b)) return 0;
        var c = a.GetHashCode().CompareTo(b.GetHashCode());
        if (c != 0) return c;
        c = string.CompareOrdinal(a.GetType().Name, b.GetType().Name);
        if (c != 0) return c;
        c = (a, b) switch
        {
            (ConstantExpr x, ConstantExpr y) => x.Value.CompareTo(y.Value),
            (VariableExpr x, VariableExpr y) => string.CompareOrdinal(x.Name, y.Name),
            (CallExpr x, CallExpr y) => string.CompareOrdinal(x.Function, y.Function),
            (PowerExpr x, PowerExpr y) => x.Exponent.CompareTo(y.Exponent),
            _ => 0,
        };
        if (c != 0) return c;
        c = a.Children.Count.CompareTo(b.Children.Count);
        for (var i = 0; c == 0 && i < a.Children.Count; i++) c = Compare(a.Children[i], b.Children[i]);
        return c;
    }
}
