namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Replaces costly operations by cheaper ones: small integer powers by products (x² → x·x),
/// negative powers by one division, and several divisions by the same value by one reciprocal
/// and multiplications. (Division by a constant is already a multiplication by its reciprocal.)
/// </summary>
public sealed class StrengthReductionPass(Func<int, string> temporaryName) : IOptimizerPass
{
    private const int LargestExpandedPower = 4;
    private int _counter;

    public string Name => "strength reduction";

    public StrengthReductionPass() : this(i => $"rcp{i}") { }

    public CodeBlock Run(CodeBlock block)
    {
        block = NamePoweredSubexpressions(block);
        block = BlockRewriting.MapExpressions(block, e => e.Rewrite(ReducePower));
        return ShareReciprocals(block);
    }

    /// <summary>
    /// (a·b + c)² must become t·t with t = a·b + c computed once, not the expanded product of its
    /// factors, so a power of anything but a variable is named first.
    /// </summary>
    private CodeBlock NamePoweredSubexpressions(CodeBlock block)
    {
        var taken = new HashSet<string>(block.Statements.OfType<AssignmentStatement>().Select(a => a.Target), StringComparer.Ordinal);
        var named = new Dictionary<Expr, Expr>();
        var result = new List<CodeStatement>();
        foreach (var s in block.Statements)
        {
            var exprs = s.Expressions.Select(e => e.Rewrite(node =>
            {
                if (node is not PowerExpr { Base.IsLeaf: false } p || Math.Abs(p.Exponent) > LargestExpandedPower) return node.IsLeaf ? node : ExprFactory.Normalize(node);
                if (!named.TryGetValue(p.Base, out var variable))
                {
                    string name;
                    do name = temporaryName(_counter++); while (!taken.Add(name));
                    variable = ExprFactory.Variable(name);
                    named[p.Base] = variable;
                    result.Add(new AssignmentStatement(name, p.Base, false));
                }
                return new PowerExpr(variable, p.Exponent);
            })).ToArray();
            result.Add(s.WithExpressions(exprs));
        }
        return named.Count == 0 ? block : block.WithStatements(result);
    }

    private static Expr ReducePower(Expr node)
    {
        if (node is not PowerExpr p) return node.IsLeaf ? node : ExprFactory.Normalize(node);
        var magnitude = Math.Abs(p.Exponent);
        var positive = magnitude <= LargestExpandedPower
            ? ExprFactory.Product(Enumerable.Repeat(p.Base, magnitude))
            : ExprFactory.Call("pow", p.Base, ExprFactory.Constant((double)magnitude));
        return p.Exponent < 0 ? ExprFactory.Quotient(ConstantExpr.One, positive) : positive;
    }

    private CodeBlock ShareReciprocals(CodeBlock block)
    {
        var counts = new Dictionary<Expr, int>();
        foreach (var s in block.Statements)
        foreach (var e in s.Expressions)
        foreach (var node in e.DescendantsAndSelf())
            if (node is QuotientExpr q && q.Denominator is not ConstantExpr)
                counts[q.Denominator] = counts.GetValueOrDefault(q.Denominator) + 1;

        var taken = new HashSet<string>(block.Statements.OfType<AssignmentStatement>().Select(a => a.Target), StringComparer.Ordinal);
        foreach (var (denominator, count) in counts.Where(kv => kv.Value >= 2).OrderByDescending(kv => kv.Key.Size))
        {
            string name;
            do name = temporaryName(_counter++); while (!taken.Add(name));
            var reciprocal = ExprFactory.Variable(name);
            var result = new List<CodeStatement>();
            var inserted = false;
            foreach (var s in block.Statements)
            {
                var uses = s.Expressions.Any(e => e.DescendantsAndSelf().Any(n => n is QuotientExpr q && q.Denominator.Equals(denominator)));
                if (uses && !inserted)
                {
                    result.Add(new AssignmentStatement(name, ExprFactory.Quotient(ConstantExpr.One, denominator), false));
                    inserted = true;
                }
                result.Add(!uses ? s : s.WithExpressions(s.Expressions.Select(e => e.Rewrite(n =>
                    n is QuotientExpr q && q.Denominator.Equals(denominator) ? ExprFactory.Product(q.Numerator, reciprocal)
                    : n.IsLeaf ? n : ExprFactory.Normalize(n))).ToArray()));
            }
            block = block.WithStatements(result);
            _ = count;
        }
        return block;
    }
}
