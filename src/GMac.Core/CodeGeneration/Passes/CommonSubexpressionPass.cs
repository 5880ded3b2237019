namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Common-subexpression elimination across all statements: a subtree that occurs more than once
/// (or occurs once and once negated, as a − b and b − a) becomes a temporary, the one that saves
/// most operations first, until nothing repeats.
/// </summary>
public sealed class CommonSubexpressionPass(Func<int, string> temporaryName) : IOptimizerPass
{
    private int _counter;

    public string Name => "common-subexpression elimination";

    public CommonSubexpressionPass() : this(i => $"cse{i}") { }

    public CodeBlock Run(CodeBlock block)
    {
        var taken = new HashSet<string>(block.Statements.OfType<AssignmentStatement>().Select(a => a.Target), StringComparer.Ordinal);
        taken.UnionWith(block.InputText.Keys);
        for (var iteration = 0; iteration < 100_000; iteration++)
        {
            var best = FindBest(block);
            if (best is null) return block;
            string name;
            do name = temporaryName(_counter++); while (!taken.Add(name));
            block = Extract(block, best, name);
        }
        return block;
    }

    /// <summary>The canonical member of {e, −e}, so both count as one subexpression.</summary>
    private static (Expr Key, bool Negated) Canonical(Expr e)
    {
        if (e is NegateExpr n) return (n.Operand, true);
        if (e is SumExpr)
        {
            var negated = ExprFactory.Negate(e) is var ne && ne is SumExpr ? ne : null;
            if (negated is not null && negated.GetHashCode() < e.GetHashCode()) return (negated, true);
        }
        return (e, false);
    }

    private static Expr? FindBest(CodeBlock block)
    {
        var counts = new Dictionary<Expr, int>();
        foreach (var s in block.Statements)
        foreach (var root in s.Expressions)
        foreach (var node in root.DescendantsAndSelf())
        {
            if (node.IsLeaf || node is NegateExpr) continue;
            var key = Canonical(node).Key;
            if (key.IsLeaf) continue;
            counts[key] = counts.GetValueOrDefault(key) + 1;
        }
        Expr? best = null;
        var bestSaving = 0;
        foreach (var (e, count) in counts)
        {
            if (count < 2) continue;
            var saving = (count - 1) * OperationCost(e);
            if (saving > bestSaving || (saving == bestSaving && best is not null && e.Size > best.Size))
            {
                best = e;
                bestSaving = saving;
            }
        }
        return best;
    }

    private static int OperationCost(Expr e)
    {
        var block = new CodeBlock([new AssignmentStatement("x", e, true)], new Dictionary<string, string>(), new Dictionary<string, string>());
        return block.Statistics().Cost;
    }

    private static CodeBlock Extract(CodeBlock block, Expr target, string name)
    {
        var negatedTarget = ExprFactory.Negate(target);
        var variable = ExprFactory.Variable(name);
        Expr Replace(Expr root) => root.Rewrite(node =>
            node.Equals(target) ? variable
            : !node.IsLeaf && node.Equals(negatedTarget) ? ExprFactory.Negate(variable)
            : node.IsLeaf ? node : ExprFactory.Normalize(node));

        var result = new List<CodeStatement>();
        var inserted = false;
        foreach (var s in block.Statements)
        {
            if (!inserted && s.Expressions.Any(e => e.DescendantsAndSelf().Any(n => n.Equals(target) || n.Equals(negatedTarget))))
            {
                result.Add(new AssignmentStatement(name, target, false));
                inserted = true;
            }
            var exprs = s.Expressions.Select(Replace).ToArray();
            result.Add(s.WithExpressions(exprs));
        }
        return block.WithStatements(result);
    }
}
