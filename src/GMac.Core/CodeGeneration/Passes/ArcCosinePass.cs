namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// atan2(√(1 − u²), u) is acos u: the root is never negative, so both give the angle in [0, π]
/// whose cosine is u (for |u| ≤ 1; beyond, both are NaN). acos costs one call where atan2 costs
/// a call more expensive than acos plus the root, a product and a difference. When the block also
/// reads that root elsewhere (slerp divides by sin Ω = √(1 − cos² Ω)), the angle is named and the
/// root becomes its sine: still exact, two calls in all, and the divisor is the sine of the very
/// angle the block turns by, which keeps the weights sin(αΩ)/sin Ω accurate as Ω → 0.
/// </summary>
public sealed class ArcCosinePass(Func<int, string> temporaryName) : IOptimizerPass
{
    private int _counter;

    public ArcCosinePass() : this(i => $"acs{i}") { }

    public string Name => "arc cosine";

    public CodeBlock Run(CodeBlock block)
    {
        if (!block.Statements.Any(s => s.Expressions.Any(e => e.DescendantsAndSelf().Any(n => n is CallExpr { Function: "atan2" }))))
            return block;
        var definitions = new Dictionary<string, Expr>(StringComparer.Ordinal);
        foreach (var a in block.Statements.OfType<AssignmentStatement>())
            if (!a.IsOutput) definitions[a.Target] = a.Value;

        // named roots √(1 − u²) read by atan2(root, u): the root's statement becomes θ = acos u; root = sin θ
        var named = new Dictionary<string, string>(StringComparer.Ordinal); // root temporary → angle temporary
        foreach (var s in block.Statements)
        foreach (var e in s.Expressions)
        foreach (var node in e.DescendantsAndSelf())
        {
            if (node is not CallExpr { Function: "atan2" } call || call.Children[0] is not VariableExpr root) continue;
            if (named.ContainsKey(root.Name) || !definitions.TryGetValue(root.Name, out var value)) continue;
            if (UnitComplementRoot(value) is { } u && u.Equals(call.Children[1])) named[root.Name] = FreshName(block);
        }

        var statements = new List<CodeStatement>();
        var changed = false;
        foreach (var s in block.Statements)
        {
            if (s is AssignmentStatement { IsOutput: false } a && named.TryGetValue(a.Target, out var angle))
            {
                statements.Add(new AssignmentStatement(angle, ExprFactory.Call("acos", UnitComplementRoot(a.Value)!), false));
                statements.Add(new AssignmentStatement(a.Target, ExprFactory.Call("sin", ExprFactory.Variable(angle)), false));
                changed = true;
                continue;
            }
            var exprs = s.Expressions.Select(e => BlockRewriting.ReplaceNodes(e, node => Rewrite(node, named))).ToArray();
            if (exprs.Where((x, k) => !ReferenceEquals(x, s.Expressions[k])).Any())
            {
                statements.Add(s.WithExpressions(exprs));
                changed = true;
            }
            else statements.Add(s);
        }
        return changed ? block.WithStatements(statements) : block;
    }

    /// <summary>atan2 of a named root: the angle's name; of a root written in place: acos u.</summary>
    private static Expr? Rewrite(Expr node, Dictionary<string, string> named)
    {
        if (node is not CallExpr { Function: "atan2" } call) return null;
        var (y, x) = (call.Children[0], call.Children[1]);
        if (y is VariableExpr v && named.TryGetValue(v.Name, out var angle)) return ExprFactory.Variable(angle);
        return UnitComplementRoot(y) is { } u && u.Equals(x) ? ExprFactory.Call("acos", x) : null;
    }

    /// <summary>u when e is √(1 − u·u), else null.</summary>
    private static Expr? UnitComplementRoot(Expr e)
    {
        if (e is not CallExpr { Function: "sqrt" } root || root.Children[0] is not SumExpr { Children.Count: 2 } sum) return null;
        var (first, second) = (sum.Children[0], sum.Children[1]);
        if (second is ConstantExpr) (first, second) = (second, first);
        if (first is not ConstantExpr { Value: 1.0 }) return null;
        return second is NegateExpr { Operand: ProductExpr { Children: [var f, var g] } } && f.Equals(g) ? f : null;
    }

    private string FreshName(CodeBlock block)
    {
        var taken = new HashSet<string>(block.Statements.OfType<AssignmentStatement>().Select(a => a.Target), StringComparer.Ordinal);
        string name;
        do name = temporaryName(_counter++); while (taken.Contains(name));
        return name;
    }
}
